// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The γc(A, f) surface as a projected wireframe net, like Figs. 28–33 of Furgerson (1980):
// lines parallel to the A and f axes following the surface, hidden lines removed by painting
// the net's cells back to front (each cell filled white, then outlined). Vector output only.

#include "report/FigureData.h"

#include <QPainter>
#include <QRectF>

namespace kinstab::report {

struct WireframeView {
    double azimuthDeg = 40;    // rotation of the (A, f) plane about the γ axis
    double elevationDeg = 28;  // height of the eye above the (A, f) plane
    double heightRatio = 0.55; // box height / box width before projection
};

// overlay: the A_crit(f) curve is drawn on the floor of the net; codes and the design point
// are not (they lie outside the usual A range of the net).
void paintWireframe(QPainter& p, const QRectF& area, const SurfaceData& s,
                    const DesignOverlay& overlay, const QString& gammaLabel,
                    const WireframeView& view = {});

} // namespace kinstab::report
