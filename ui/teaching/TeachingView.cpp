// SPDX-License-Identifier: GPL-3.0-or-later
// TeachingView (ui/teaching/TeachingView.h): its construction, the keys, the run and the frame
// shown. The side panel is in TeachingViewSide.cpp, the saved frames in TeachingViewExport.cpp.
#include "ui/teaching/TeachingView.h"
#include "ui/teaching/TransportBar.h"

#include "ui/teaching/EventLog.h"
#include "ui/teaching/ParameterPanel.h"
#include "ui/teaching/SlabAnimation.h"
#include "ui/teaching/SurfaceMarker.h"
#include "ui/teaching/TeachingPlayer.h"
#include "ui/teaching/TracePlot.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QShortcut>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <algorithm>

namespace kinstab::ui {

TeachingView::TeachingView(QWidget* parent)
    : QWidget(parent), run_(std::make_unique<TeachingRun>()), player_(new TeachingPlayer(this)),
      animation_(new SlabAnimation(this)), traces_(new TracePlot(this)),
      panel_(new ParameterPanel(this)), marker_(new SurfaceMarker(this)), log_(new EventLog(this)) {
    auto* left = new QVBoxLayout;
    left->addWidget(animation_, 5);
    left->addWidget(traces_, 4);
    left->addWidget(buildTransport());
    auto* root = new QHBoxLayout(this);
    // Narrow margins: the tab at 1280 × 800 is about 400 px tall, and the scene, the traces and
    // the play bar must all fit in it (ui/teaching/SlabAnimation.h, TracePlot.h).
    root->setContentsMargins(4, 4, 4, 4);
    root->addLayout(left, 1);
    root->addWidget(buildSidePanel());

    connect(player_, &TeachingPlayer::tauChanged, this, &TeachingView::showFrame);
    connect(traces_, &TracePlot::seekRequested, player_, &TeachingPlayer::seek);
    connect(log_, &EventLog::eventClicked, player_, &TeachingPlayer::seekToEvent);
    connect(panel_, &ParameterPanel::paramsChanged, this, [this](const TeachingParams& p) {
        presetId_.clear();
        rerun(p);
    });
    connect(marker_, &SurfaceMarker::pointPicked, this, &TeachingView::showPoint);
    installKeys();
    applyPreset(QStringLiteral("fig29"));
}

TeachingView::~TeachingView() = default;

// Space plays and pauses, the arrows step, N and B jump between events, wherever the focus is
// inside the view: the scene and the traces take the focus when clicked, so a click on them
// does not leave the keys with the scroll area around the view.
void TeachingView::installKeys() {
    animation_->setFocusPolicy(Qt::ClickFocus);
    traces_->setFocusPolicy(Qt::ClickFocus);
    transport_->installKeys(this);
    auto key = [this](QKeyCombination k, auto slot) {
        auto* s =
            new QShortcut(QKeySequence(k), this, nullptr, nullptr, Qt::WidgetWithChildrenShortcut);
        connect(s, &QShortcut::activated, this, slot);
    };
    key(Qt::Key_Right, [this] { stepFrames(1); });
    key(Qt::Key_Left, [this] { stepFrames(-1); });
    key(Qt::SHIFT | Qt::Key_Right, [this] { stepFrames(25); });
    key(Qt::SHIFT | Qt::Key_Left, [this] { stepFrames(-25); });
}

void TeachingView::stepFrames(int frames) {
    player_->pause();
    const double tstar = run_->tstar() > 0 ? run_->tstar() : 0.1;
    player_->seek(player_->tau() + frames * player_->speed() / 25.0 / tstar);
}

void TeachingView::setUnitSystem(UnitSystem s) {
    units_ = s;
    panel_->setUnitSystem(s);
    showFrame(player_->tau());
}

QWidget* TeachingView::buildTransport() {
    transport_ = new TransportBar(
        player_, [this] { return run_->displayEnd(); },
        {tr("Next event (N)"),
         tr("Speed: 1× is real time for this wall (τ advances 1/t* per second)"), 170},
        this);
    transport_->setObjectName(QStringLiteral("transport"));
    return transport_;
}

TeachingParams TeachingView::params() const {
    return run_->params();
}

DisplayState TeachingView::displayedState() const {
    return animation_->scene().frame.state;
}

void TeachingView::setParams(const TeachingParams& p) {
    panel_->setParams(p);
    presetId_.clear();
    rerun(p);
}

void TeachingView::showPoint(double amplitude, double frequencyHz) {
    TeachingParams p = run_->params();
    p.amplitude = amplitude;
    p.frequencyHz = frequencyHz;
    setParams(p);
}

bool TeachingView::applyPreset(const QString& id) {
    const FigurePreset* preset = findFigurePreset(id);
    if (!preset) return false;
    presetId_ = id;
    mapMode_ = preset->mode;
    mapRange_ = preset->range;
    caption_->setText(
        QStringLiteral("Furgerson (1980), %1: %2").arg(preset->figure, preset->caption));
    panel_->setParams(preset->params);
    rerun(preset->params);
    player_->rewind();
    emit presetApplied(id);
    return true;
}

void TeachingView::rerun(const TeachingParams& p) {
    run_ = std::make_unique<TeachingRun>(p);
    traces_->setRun(run_.get());
    log_->setEvents(run_->events(), run_->tstar());
    marker_->setContext(p, mapRange_, mapMode_);
    {
        const QSignalBlocker block(presets_);
        presets_->setCurrentIndex(std::max(0, presets_->findData(presetId_)));
    }
    if (presetId_.isEmpty()) caption_->clear();
    updateOutcome();
    player_->setRun(run_->eventTimes(), run_->displayEnd(), run_->tstar()); // shows the frame
    emit runChanged();
    emit paramsChanged(p);
}

void TeachingView::showFrame(double tau) {
    const TeachingFrame f = run_->frameAt(tau);
    animation_->setScene(
        SlabScene{f, run_->params(), run_->tstar(), run_->displayEnd(), run_->exitSide(), units_});
    traces_->setCursor(tau);
    log_->setCurrent(f.eventIndex);
    transport_->showPosition(tau, QStringLiteral("τ %1 / %2   t %3 s")
                                      .arg(tau, 0, 'f', 2)
                                      .arg(run_->displayEnd(), 0, 'f', 1)
                                      .arg(tau * run_->tstar(), 0, 'f', 2));
    emit frameChanged(tau);
}

} // namespace kinstab::ui
