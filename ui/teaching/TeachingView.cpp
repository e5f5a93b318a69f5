// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/teaching/TeachingView.h"
#include "ui/teaching/TransportBar.h"

#include "ui/ProjectFolder.h"
#include "ui/teaching/EventLog.h"
#include "ui/teaching/FrameExport.h"
#include "ui/teaching/ParameterPanel.h"
#include "ui/teaching/SlabAnimation.h"
#include "ui/teaching/StateStyle.h"
#include "ui/teaching/SurfaceMarker.h"
#include "ui/teaching/TeachingPlayer.h"
#include "ui/teaching/TracePlot.h"

#include <QApplication>
#include <QComboBox>
#include <QFileDialog>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QMessageBox>
#include <QProgressDialog>
#include <QPushButton>
#include <QScrollArea>
#include <QShortcut>
#include <QSignalBlocker>
#include <QSlider>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <iterator>

namespace kinstab::ui {

namespace {} // namespace

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

void TeachingView::setFontScale(double scale) {
    fontScale_ = std::clamp(scale, 0.5, 4.0);
    QFont f = QApplication::font();
    f.setPointSizeF(f.pointSizeF() * fontScale_);
    setFont(f);
    // The side panel grows with its text, up to a third of a full-HD screen.
    side_->setFixedWidth(static_cast<int>(350 * std::min(fontScale_, 1.8)));
    {
        const QSignalBlocker block(fontScaleBox_);
        int best = 0;
        for (int i = 0; i < fontScaleBox_->count(); ++i)
            if (std::abs(fontScaleBox_->itemData(i).toDouble() - fontScale_) <
                std::abs(fontScaleBox_->itemData(best).toDouble() - fontScale_))
                best = i;
        fontScaleBox_->setCurrentIndex(best);
    }
    animation_->update();
    traces_->update();
    marker_->update();
    emit fontScaleChanged(fontScale_);
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

// The text size sits beside the presets, not in the play bar: there it made the bar wider
// than the tab at 1280 × 800 (the whole view scrolled sideways, cutting the side panel).
QComboBox* TeachingView::buildFontScaleBox() {
    fontScaleBox_ = new QComboBox;
    fontScaleBox_->setObjectName(QStringLiteral("fontScale"));
    for (double f : {1.0, 1.5, 2.0, 2.5, 3.0})
        fontScaleBox_->addItem(tr("Text %1%").arg(f * 100, 0, 'f', 0), f);
    fontScaleBox_->setToolTip(tr("Text size, for a projector (F11: presentation mode)"));
    connect(fontScaleBox_, &QComboBox::activated, this,
            [this](int i) { setFontScale(fontScaleBox_->itemData(i).toDouble()); });
    return fontScaleBox_;
}

QWidget* TeachingView::buildSidePanel() {
    auto* side = new QWidget;
    auto* v = new QVBoxLayout(side);
    v->setContentsMargins(0, 0, 0, 0);
    presets_ = new QComboBox(side);
    presets_->addItem(tr("(your own settings)"), QString());
    for (const FigurePreset& p : figurePresets())
        presets_->addItem(presetListText(p), p.id);
    presets_->setToolTip(tr("Reproduce a figure of Furgerson (1980) in one click"));
    connect(presets_, &QComboBox::activated, this, [this](int i) {
        const QString id = presets_->itemData(i).toString();
        if (!id.isEmpty()) applyPreset(id);
    });
    presets_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
    presets_->setMinimumContentsLength(10);
    auto* top = new QHBoxLayout;
    top->addWidget(presets_, 1);
    top->addWidget(buildFontScaleBox());
    v->addLayout(top);
    caption_ = new QLabel(side);
    caption_->setWordWrap(true);
    caption_->setStyleSheet(QStringLiteral("color: #555;"));
    v->addWidget(caption_);
    v->addWidget(panel_);
    outcome_ = new QLabel(side);
    outcome_->setWordWrap(true);
    outcome_->setTextFormat(Qt::RichText);
    v->addWidget(outcome_);
    marker_->setMinimumHeight(230);
    v->addWidget(marker_);
    v->addWidget(log_, 1);
    auto* exports = new QHBoxLayout;
    auto* frame = new QPushButton(tr("Save frame…"), side);
    frame->setToolTip(tr("The current frame as PNG or SVG"));
    connect(frame, &QPushButton::clicked, this, &TeachingView::exportFrameDialog);
    auto* seq = new QPushButton(tr("Save run as PNGs…"), side);
    seq->setToolTip(tr("Every frame of the run at 25 frames per second and the current speed"));
    connect(seq, &QPushButton::clicked, this, &TeachingView::exportSequenceDialog);
    exports->addWidget(frame);
    exports->addWidget(seq);
    v->addLayout(exports);
    // Scrolls on its own: a taller panel (the planar model's extra fields, large text) must
    // not push the play bar below the window.
    auto* scroll = new QScrollArea(this);
    scroll->setWidget(side);
    scroll->setWidgetResizable(true);
    scroll->setFrameShape(QFrame::NoFrame);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    scroll->setFixedWidth(350);
    side_ = scroll;
    return scroll;
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

void TeachingView::updateOutcome() {
    const TeachingRun& r = *run_;
    if (!r.error().empty()) {
        outcome_->setText(QStringLiteral("<span style='color:#c0392b'>%1</span>")
                              .arg(QString::fromStdString(r.error()).toHtmlEscaped()));
        return;
    }
    const SlabResult& s = r.result();
    const QString timing =
        tr("%1 events, run %2 ms").arg(r.events().size()).arg(r.runSeconds() * 1e3, 0, 'f', 2);
    const QString where = !r.planar()                       ? QString()
                          : r.exitSide() == ExitSide::Along ? tr(" along the walls")
                                                            : tr(" across the walls");
    if (s.outcome == Outcome::Collapsed)
        outcome_->setText(tr("<b style='color:%1'>Collapses</b>%7 at τc = %2 (t = %3 s): γc = "
                             "%4<br>%5 slip intervals; %6")
                              .arg(stateColor(DisplayState::Collapse).name())
                              .arg(s.tauC, 0, 'f', 2)
                              .arg(s.tauC * r.tstar(), 0, 'f', 2)
                              .arg(r.gammaC(), 0, 'f', 3)
                              .arg(s.slipIntervals)
                              .arg(timing)
                              .arg(where));
    else
        outcome_->setText(tr("<b style='color:%1'>Stable</b>: max |δ| = %2, residual δ = %3<br>%4 "
                             "slip intervals; %5")
                              .arg(stateColor(DisplayState::Stable).name())
                              .arg(s.maxAbsDelta, 0, 'f', 3)
                              .arg(s.residualDelta, 0, 'f', 3)
                              .arg(s.slipIntervals)
                              .arg(timing));
}

QString TeachingView::exportFramePng(const QString& path, QSize size) const {
    return saveFramePng(path, *run_, player_->tau(), size, units_);
}

QString TeachingView::exportFrameSvg(const QString& path, QSize size) const {
    return saveFrameSvg(path, *run_, player_->tau(), size, units_);
}

int TeachingView::exportSequence(const QString& directory, double framesPerSecond, QSize size,
                                 QString* error) {
    SequenceOptions o;
    o.framesPerSecond = framesPerSecond;
    o.speed = player_->speed();
    o.size = size;
    o.units = units_;
    const SequenceResult r = saveFrameSequence(directory, *run_, o);
    if (error) *error = r.error;
    return r.error.isEmpty() ? r.frames : 0;
}

void TeachingView::exportFrameDialog() {
    QString filter;
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Save frame"), inOpenProjectFolder("teaching-frame.png"),
        tr("PNG image (*.png);;SVG drawing (*.svg)"), &filter);
    if (path.isEmpty()) return;
    const bool svg = path.endsWith(QStringLiteral(".svg"), Qt::CaseInsensitive) ||
                     filter.contains(QStringLiteral("svg"));
    const QString err = svg ? exportFrameSvg(path) : exportFramePng(path);
    if (!err.isEmpty()) QMessageBox::warning(this, tr("Save frame"), err);
}

void TeachingView::exportSequenceDialog() {
    const QString dir = QFileDialog::getExistingDirectory(this, tr("Folder for the PNG sequence"));
    if (dir.isEmpty()) return;
    player_->pause();
    QProgressDialog progress(tr("Writing frames…"), tr("Cancel"), 0, 100, this);
    progress.setWindowModality(Qt::WindowModal);
    SequenceOptions o;
    o.speed = player_->speed();
    o.units = units_;
    const SequenceResult r = saveFrameSequence(dir, *run_, o, [&](int done, int total) {
        progress.setMaximum(total);
        progress.setValue(done);
        return !progress.wasCanceled();
    });
    if (!r.error.isEmpty()) QMessageBox::warning(this, tr("Save run"), r.error);
}

} // namespace kinstab::ui
