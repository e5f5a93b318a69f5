// SPDX-License-Identifier: GPL-3.0-or-later
// TeachingView, continued: the side panel - the figure presets, the text size, the parameters,
// the run's outcome line, the surface marker, the event log and the save buttons.

#include "ui/teaching/EventLog.h"
#include "ui/teaching/ParameterPanel.h"
#include "ui/teaching/SidePanel.h"
#include "ui/teaching/SlabAnimation.h"
#include "ui/teaching/StateStyle.h"
#include "ui/teaching/SurfaceMarker.h"
#include "ui/teaching/TeachingView.h"
#include "ui/teaching/TracePlot.h"

#include <QApplication>
#include <QComboBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace kinstab::ui {

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

// The figure presets beside the text size.
QHBoxLayout* TeachingView::buildPresetRow(QWidget* side) {
    presets_ = presetBox(side, tr("Reproduce a figure of Furgerson (1980) in one click"));
    presets_->addItem(tr("(your own settings)"), QString());
    for (const FigurePreset& p : figurePresets())
        presets_->addItem(presetListText(p), p.id);
    connect(presets_, &QComboBox::activated, this, [this](int i) {
        const QString id = presets_->itemData(i).toString();
        if (!id.isEmpty()) applyPreset(id);
    });
    auto* top = new QHBoxLayout;
    top->addWidget(presets_, 1);
    top->addWidget(buildFontScaleBox());
    return top;
}

QHBoxLayout* TeachingView::buildExportRow(QWidget* side) {
    auto* exports = new QHBoxLayout;
    auto* frame = new QPushButton(tr("Save frame…"), side);
    frame->setToolTip(tr("The current frame as PNG or SVG"));
    connect(frame, &QPushButton::clicked, this, &TeachingView::exportFrameDialog);
    auto* seq = new QPushButton(tr("Save run as PNGs…"), side);
    seq->setToolTip(tr("Every frame of the run at 25 frames per second and the current speed"));
    connect(seq, &QPushButton::clicked, this, &TeachingView::exportSequenceDialog);
    exports->addWidget(frame);
    exports->addWidget(seq);
    return exports;
}

QWidget* TeachingView::buildSidePanel() {
    const SideColumn side = sideColumn();
    QVBoxLayout* v = side.layout;
    v->addLayout(buildPresetRow(side.widget));
    caption_ = captionLabel(side.widget);
    v->addWidget(caption_);
    v->addWidget(panel_);
    outcome_ = outcomeLabel(side.widget);
    v->addWidget(outcome_);
    marker_->setMinimumHeight(230);
    v->addWidget(marker_);
    v->addWidget(log_, 1);
    v->addLayout(buildExportRow(side.widget));
    // Scrolls on its own: a taller panel (the planar model's extra fields, large text) must
    // not push the play bar below the window.
    side_ = sideScroll(side.widget);
    return side_;
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

} // namespace kinstab::ui
