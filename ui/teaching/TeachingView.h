// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Teaching view: the slab on its walls, animated in step with one run, the traces with a
// cursor, the transport (play, pause, speed, scrub, event steps), the event log, parameter
// sliders that re-run at once, the "where am I" map and one-click presets for the paper's
// figures. Self-contained: the main window docks it as a tab.

#include "ui/Units.h"
#include "ui/teaching/FigurePresets.h"
#include "ui/teaching/TeachingRun.h"

#include <QWidget>

#include <memory>

class QComboBox;
class QHBoxLayout;
class QLabel;
class QPushButton;
class QSlider;
class QToolButton;

namespace kinstab::ui {

class EventLog;
class ParameterPanel;
class SlabAnimation;
class SurfaceMarker;
class TeachingPlayer;
class TracePlot;
class TransportBar;

class TeachingView : public QWidget {
    Q_OBJECT
public:
    explicit TeachingView(QWidget* parent = nullptr);
    ~TeachingView() override;

    const TeachingRun& run() const { return *run_; }
    TeachingParams params() const;
    TeachingPlayer* player() const { return player_; }
    ParameterPanel* parameterPanel() const { return panel_; }
    EventLog* eventLog() const { return log_; }
    SurfaceMarker* surfaceMarker() const { return marker_; }
    SlabAnimation* animation() const { return animation_; }
    TracePlot* tracePlot() const { return traces_; }
    // What the drawing shows now.
    DisplayState displayedState() const;
    QString currentPresetId() const { return presetId_; }
    MapMode mapMode() const { return mapMode_; }
    MapRange mapRange() const { return mapRange_; }
    // Text size relative to the application's font (1 = normal; presentation mode uses more),
    // for the panels and the painted scene alike.
    double fontScale() const { return fontScale_; }

    // Exports of the current frame / the whole run; empty string or frame count on success.
    QString exportFramePng(const QString& path, QSize size = {1280, 900}) const;
    QString exportFrameSvg(const QString& path, QSize size = {1280, 900}) const;
    int exportSequence(const QString& directory, double framesPerSecond, QSize size,
                       QString* error = nullptr);

public slots:
    void setParams(const kinstab::ui::TeachingParams& p); // re-runs at once, keeps the time
    bool applyPreset(const QString& id);                  // false for an unknown id
    // Show the run at (A, f) with the rest unchanged: e.g. a point picked on the main surface.
    void showPoint(double amplitude, double frequencyHz);
    void setFontScale(double scale);               // clamped to [0.5, 4]
    void setUnitSystem(kinstab::ui::UnitSystem s); // lengths in the panel and the drawing

signals:
    void runChanged();
    void paramsChanged(const kinstab::ui::TeachingParams& p);
    void presetApplied(const QString& id);
    void fontScaleChanged(double scale);
    void frameChanged(double tau);

private:
    QWidget* buildTransport();
    QComboBox* buildFontScaleBox();
    QWidget* buildSidePanel();
    QHBoxLayout* buildPresetRow(QWidget* side);
    QHBoxLayout* buildExportRow(QWidget* side);
    void rerun(const TeachingParams& p);
    void showFrame(double tau);
    void updateOutcome();
    void exportFrameDialog();
    void exportSequenceDialog();
    void installKeys();
    void stepFrames(int frames); // pauses, then moves by frames of 1/25 s at the current speed

    std::unique_ptr<TeachingRun> run_;
    TeachingPlayer* player_;
    SlabAnimation* animation_;
    TracePlot* traces_;
    ParameterPanel* panel_;
    SurfaceMarker* marker_;
    EventLog* log_;
    QComboBox* presets_;
    QLabel* caption_;
    QLabel* outcome_;
    TransportBar* transport_ = nullptr;
    QComboBox* fontScaleBox_;
    QWidget* side_ = nullptr;
    double fontScale_ = 1.0;
    UnitSystem units_ = UnitSystem::SI;
    QString presetId_;
    MapMode mapMode_ = MapMode::Surface;
    MapRange mapRange_;
};

} // namespace kinstab::ui
