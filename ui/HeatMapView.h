// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The 2D stand-in for the 3D γc surface when OpenGL is not available (headless, remote
// desktops): γc(A, f) as a colour map with the same overlays, selectable by click.

#include "ui/SurfaceData.h"

#include <QWidget>

namespace kinstab::ui {

class HeatMapView : public QWidget {
    Q_OBJECT
public:
    explicit HeatMapView(QWidget* parent = nullptr);

    void setData(const GammaGrid& g);
    void setOverlays(const SurfaceOverlays& o);
    void setSelected(int ai, int fi);
    // Dims the map: it was computed with other inputs than the panels now show.
    void setStale(bool stale);
    QSize sizeHint() const override { return {500, 400}; }

signals:
    void pointSelected(int ai, int fi);

protected:
    void paintEvent(QPaintEvent*) override;
    void mousePressEvent(QMouseEvent* e) override;

private:
    QRectF plotRect() const;
    double xOf(double a) const;
    double yOf(double f) const;
    void updateRanges();
    void paintCells(QPainter& p) const;
    void paintOverlays(QPainter& p) const;
    void paintAxes(QPainter& p) const;

    GammaGrid m_grid;
    SurfaceOverlays m_overlays;
    double m_aMin = 0, m_aMax = 1, m_fMin = 0, m_fMax = 1, m_gMax = 1;
    int m_selA = -1, m_selF = -1;
    bool m_stale = false;
};

// What the surface area says before anything is computed.
QString emptyHint();

} // namespace kinstab::ui
