// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The γc(A, f) surface. All Qt Data Visualization code lives in this class (the module is
// deprecated after Qt 6.10, so a port touches one file). Without an OpenGL context it shows
// the 2D HeatMapView instead, with the same interface.

#include "ui/SurfaceData.h"

#include <QWidget>

#include <memory>

class QLabel;

namespace kinstab::ui {

class HeatMapView;

class SurfaceView : public QWidget {
    Q_OBJECT
public:
    explicit SurfaceView(QWidget* parent = nullptr);
    ~SurfaceView() override;

    bool is3D() const { return m_3d != nullptr; }
    void setData(const GammaGrid& g);
    void setOverlays(const SurfaceOverlays& o);
    // Selects (and reports) the point amplitudes[ai], frequencies[fi].
    void selectPoint(int ai, int fi);
    // The view as an image (renderToImage for the 3D view: grab() of a GL window is blank).
    QImage renderImage(QSize size);
    // The widget showing the graph (the GL window's container, or the heat map).
    QWidget* graphWidget() const;
    // The selected point after a click (ai, fi), or (-1, -1).
    QPoint selected() const { return m_selected; }
    const GammaGrid& data() const { return m_grid; }
    const SurfaceOverlays& overlays() const { return m_overlays; }
    // A line above the graph saying why it shows nothing (e.g. a record has no (A, f) surface);
    // empty hides it.
    void setNotice(const QString& text);
    QString notice() const;
    // Marks the shown surface as computed with other inputs: dimmed, with a line saying so.
    void setStale(bool stale);
    bool isStale() const { return m_stale; }
    // Grid points shown as "not computed" (NaN γc after a Cancel), distinct from stable.
    int notComputedCount() const;
    QString legendText() const;

signals:
    void pointSelected(int ai, int fi);

private:
    struct Graph3D; // the Data Visualization objects
    void updateLegend();
    void rebuildOverlays();

    std::unique_ptr<Graph3D> m_3d;
    HeatMapView* m_map = nullptr;
    QLabel* m_legend;
    QLabel* m_notice;
    QLabel* m_staleLine;
    bool m_stale = false;
    GammaGrid m_grid;
    SurfaceOverlays m_overlays;
    QPoint m_selected{-1, -1};
};

} // namespace kinstab::ui
