// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/teaching/BlockTeachingView.h"
#include "ui/teaching/TransportBar.h"

#include "ui/teaching/BlockAnimation.h"
#include "ui/teaching/BlockPresets.h"
#include "ui/teaching/SidePanel.h"
#include "ui/teaching/TeachingPlayer.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QSignalBlocker>
#include <QSlider>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>

#include <cmath>

namespace kinstab::ui {

namespace {
// How long an impact flashes in the drawing, s of the run.
constexpr double kImpactFlash = 0.04;
} // namespace

BlockTeachingView::BlockTeachingView(QWidget* parent)
    : QWidget(parent), run_(std::make_unique<BlockRun>()), player_(new TeachingPlayer(this)),
      animation_(new BlockAnimation(this)), traces_(new BlockTraces(this)) {
    setObjectName(QStringLiteral("blockTeachingView"));
    auto* left = new QVBoxLayout;
    left->addWidget(animation_, 5);
    left->addWidget(traces_, 3);
    left->addWidget(buildTransport());
    auto* root = new QHBoxLayout(this);
    root->setContentsMargins(4, 4, 4, 4);
    root->addLayout(left, 1);
    root->addWidget(buildSidePanel());
    connect(player_, &TeachingPlayer::tauChanged, this, &BlockTeachingView::showFrame);
    connect(traces_, &BlockTraces::seekRequested, player_, &TeachingPlayer::seek);
    player_->setSpeed(kDefaultSpeed);
    installKeys();
    applyPreset(blockPresets().front().id);
}

// The slab's keys (TeachingView): space plays and pauses, N and B step between events, wherever
// the focus is inside the view.
void BlockTeachingView::installKeys() {
    animation_->setFocusPolicy(Qt::ClickFocus);
    traces_->setFocusPolicy(Qt::ClickFocus);
    transport_->installKeys(this);
}

BlockTeachingView::~BlockTeachingView() = default;

QSlider* BlockTeachingView::scrubber() const {
    return transport_->scrubber();
}

QWidget* BlockTeachingView::buildTransport() {
    transport_ = new TransportBar(
        player_, [this] { return run_->end(); },
        {tr("Next event: impact, mode change, overturning (N)"), tr("Speed: 1× is real time"), 120},
        this);
    transport_->setObjectName(QStringLiteral("blockTransport"));
    transport_->scrubber()->setObjectName(QStringLiteral("blockScrub"));
    return transport_;
}

QWidget* BlockTeachingView::buildSidePanel() {
    const SideColumn side = sideColumn();
    QVBoxLayout* v = side.layout;
    presets_ =
        presetBox(side.widget, tr("A published case of the rocking literature in one click"));
    presets_->setObjectName(QStringLiteral("blockPresets"));
    for (const BlockPreset& p : blockPresets())
        presets_->addItem(QStringLiteral("%1 · %2").arg(p.title, p.source), p.id);
    connect(presets_, &QComboBox::activated, this,
            [this](int i) { applyPreset(presets_->itemData(i).toString()); });
    v->addWidget(presets_);
    caption_ = captionLabel(side.widget);
    v->addWidget(caption_);
    outcome_ = outcomeLabel(side.widget);
    v->addWidget(outcome_);
    events_ = new QListWidget(side.widget);
    events_->setToolTip(tr("Click an event to go to it"));
    connect(events_, &QListWidget::itemClicked, this, [this](QListWidgetItem* item) {
        player_->pause();
        player_->seek(item->data(Qt::UserRole).toDouble());
    });
    v->addWidget(events_, 1);
    return sideScroll(side.widget);
}

bool BlockTeachingView::applyPreset(const QString& id) {
    const BlockPreset* preset = findBlockPreset(id);
    if (!preset) return false;
    presetId_ = id;
    {
        const QSignalBlocker block(presets_);
        presets_->setCurrentIndex(presets_->findData(id));
    }
    caption_->setText(QStringLiteral("%1: %2").arg(preset->source, preset->caption));
    rerun(preset->blockCase);
    player_->rewind();
    return true;
}

void BlockTeachingView::setCase(const BlockCase& c) {
    presetId_.clear();
    caption_->clear();
    rerun(c);
}

void BlockTeachingView::setUnitSystem(UnitSystem s) {
    units_ = s;
    updateOutcome();
    showFrame(player_->tau());
}

void BlockTeachingView::rerun(const BlockCase& c) {
    run_ = std::make_unique<BlockRun>(c);
    traces_->setRun(run_.get());
    events_->clear();
    const RockingResult& r = run_->result();
    for (double t : run_->eventTimes()) {
        const bool impact =
            std::find(r.impactTimes.begin(), r.impactTimes.end(), t) != r.impactTimes.end();
        const bool over = r.overturnTime && *r.overturnTime == t;
        const RockingSample s = run_->at(t);
        const QString what =
            over     ? tr("overturned")
            : impact ? tr("impact, rocks on about the other corner")
                     : tr("starts to %1")
                           .arg(QString::fromUtf8(blockModeName(s.mode).data(),
                                                  static_cast<int>(blockModeName(s.mode).size())));
        auto* item = new QListWidgetItem(tr("t = %1 s: %2").arg(t, 0, 'f', 3).arg(what), events_);
        item->setData(Qt::UserRole, t);
    }
    updateOutcome();
    player_->setRun(run_->eventTimes(), run_->end(), 1.0); // time in seconds; shows the frame
    emit runChanged();
}

RockingSample BlockTeachingView::displayedState() const {
    return animation_->scene().state;
}

void BlockTeachingView::showFrame(double t) {
    BlockScene sc;
    sc.block = run_->blockCase().model.block;
    sc.state = run_->at(t);
    sc.baseAcceleration = run_->baseAcceleration(t);
    sc.overturned = run_->overturnedBy(t);
    sc.impact = run_->impactNear(t, kImpactFlash).has_value();
    sc.units = units_;
    animation_->setScene(sc);
    traces_->setCursor(t);
    transport_->showPosition(t, tr("t %1 / %2 s").arg(t, 0, 'f', 3).arg(run_->end(), 0, 'f', 2));
}

void BlockTeachingView::updateOutcome() {
    const BlockRun& r = *run_;
    if (!r.error().empty()) {
        outcome_->setText(QStringLiteral("<span style='color:#c0392b'>%1</span>")
                              .arg(QString::fromStdString(r.error()).toHtmlEscaped()));
        return;
    }
    const RockingResult& res = r.result();
    const std::string_view name = rockingOutcomeName(res.outcome);
    const double perUnit = metresPerDisplayUnit(units_, LengthScale::Detail);
    QString text =
        tr("<b>%1</b>: max |θ|/α = %2, impacts: %3, sliding %4 %5")
            .arg(QString::fromUtf8(name.data(), static_cast<int>(name.size())))
            .arg(res.maxThetaOverAlpha, 0, 'f', 3)
            .arg(res.impactTimes.size())
            .arg(res.slidingDisplacement / perUnit, 0, 'f', units_ == UnitSystem::US ? 2 : 1)
            .arg(lengthSymbol(units_, LengthScale::Detail));
    if (res.overturnTime) text += tr("; overturned at t = %1 s").arg(*res.overturnTime, 0, 'f', 3);
    text += tr("<br>α = %1 rad, p = %2 rad/s, η = %3")
                .arg(r.alpha(), 0, 'f', 4)
                .arg(r.p(), 0, 'f', 3)
                .arg(restitutionOf(r.blockCase().model), 0, 'f', 3);
    outcome_->setText(text);
}

} // namespace kinstab::ui
