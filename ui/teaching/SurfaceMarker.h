// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// "Where am I on the surface": a coarse gamma_c(A, f) map (or, for Fig. 34, tau_c against A at
// the current f) of the current envelope, mu and wall, with the current run marked. The
// sweep runs on a BackgroundJob; a change while it runs supersedes it (its result is dropped).

#include "core/sweep/Sweep.h"
#include "ui/BackgroundJob.h"
#include "ui/teaching/FigurePresets.h"

#include <QWidget>

namespace kinstab::ui {

struct MarkerMap {
    TeachingParams context; // what the sweep was run for (A, f ignored except f in Slice mode)
    MapRange range;
    MapMode mode = MapMode::Surface;
    SweepResult sweep;
    std::vector<double> gamma; // gamma_c per point, as sweep.points
    double tauRef = 1;
};

// What a sweep depends on (the current point's A, and f for a surface, do not count).
struct SweepKey {
    TeachingParams params;
    MapRange range;
    MapMode mode = MapMode::Surface;
};
bool sameSweep(const SweepKey& a, const SweepKey& b);

class SurfaceMarker : public QWidget {
    Q_OBJECT
public:
    static constexpr int kCells = 24;       // 24 x 24 surface
    static constexpr int kPlanarCells = 14; // planar runs cost more: the paper's 14 A_x values
    static constexpr int kSlicePoints = 46; // A every 0.01 over the paper's 0.7..1.15

    explicit SurfaceMarker(QWidget* parent = nullptr);
    ~SurfaceMarker() override; // job_ cancels and waits

    // Re-sweeps only when something but the current point changed.
    void setContext(const TeachingParams& p, const MapRange& range, MapMode mode);
    const MarkerMap& map() const { return map_; }
    bool isComputing() const { return job_.isRunning(); }
    bool hasMap() const { return hasMap_; }
    QSize sizeHint() const override { return {320, 250}; }
    QSize minimumSizeHint() const override { return {220, 180}; }
    // The map's cells inside the widget; the margins around it follow the font's size.
    QRectF plotRect() const;

signals:
    void pointPicked(double amplitude, double frequencyHz);
    void mapReady();

protected:
    void paintEvent(QPaintEvent*) override;
    void mousePressEvent(QMouseEvent* e) override;

private:
    void start();
    void onFinished(const MarkerMap& m);

    SweepKey current_; // what is shown and marked
    SweepKey running_; // what the worker computes
    MarkerMap map_;
    bool hasMap_ = false;
    BackgroundJob job_;
};

} // namespace kinstab::ui
