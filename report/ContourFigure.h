// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Filled contour map of γc over (A, f) with the design overlays: the A_crit(f) curve (the
// stable/collapse boundary), the code ratios as lines at A = ratio, the building frequency
// and the design points (ratio, 1/T). Bands are exact polygons of the piecewise-linear
// interpolant on a triangulated grid, so the map is vector art at any zoom.

#include "report/FigureData.h"

#include <QPainter>
#include <QRectF>

namespace kinstab::report {

void paintContourMap(QPainter& p, const QRectF& area, const SurfaceData& s,
                     const DesignOverlay& overlay, const QString& gammaLabel);

} // namespace kinstab::report
