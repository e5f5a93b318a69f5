// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The 3D γc surface's parts (ui/SurfaceView.h): the graph a view holds when OpenGL is there, the
// axes, arrays, gradient and overlay series it is built from, and the overlays drawn on it (code
// ratios, building frequency, axes fitted to the grid).

#include "ui/SurfaceData.h"

#include <QColor>
#include <QLinearGradient>
#include <QString>
#include <QtDataVisualization/Q3DSurface>
#include <QtDataVisualization/QSurface3DSeries>
#include <QtDataVisualization/QSurfaceDataProxy>
#include <QtDataVisualization/QValue3DAxis>

#include <cstddef>
#include <functional>
#include <vector>

namespace kinstab::ui {

struct SurfaceGraph3D {
    Q3DSurface* graph = nullptr; // owned by the window container
    QWidget* container = nullptr;
    QSurface3DSeries* surface = nullptr;
    QSurface3DSeries* notComputed = nullptr; // grey patches at γc = 0 where no point was run
    std::vector<QSurface3DSeries*> overlays;
};

// A Q3DSurface with an OpenGL context, or nullptr where there is none (the offscreen platform).
Q3DSurface* makeGraph();
QValue3DAxis* makeAxis(const QString& title, const QString& format);
// Rows of points (x = xs[c], y = y(r, c), z = zs[r]); owns nothing on return: resetArray takes
// the rows.
QSurfaceDataArray* makeArray(const std::vector<float>& zs, const std::vector<float>& xs,
                             const std::function<float(std::size_t, std::size_t)>& y);
// The γc colour scale as the surface's gradient; faded for a stale surface.
QLinearGradient surfaceGradient(bool faded);
// A uniformly coloured surface series for an overlay.
QSurface3DSeries* makeOverlay(const QColor& color);
// Fits the axes to the grid and draws the overlays anew (none for an empty grid).
void drawOverlays3D(SurfaceGraph3D& g3, const GammaGrid& grid, const SurfaceOverlays& overlays);

} // namespace kinstab::ui
