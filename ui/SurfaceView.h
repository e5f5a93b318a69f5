// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The γc(A, f) surface. All Qt Data Visualization code lives in this class (the module is
// deprecated after Qt 6.10, so a port touches one file). Three ways to look at it: the 3D
// surface, the 3D surface from straight above, and the 2D colour map (HeatMapView, the only
// one without an OpenGL context). A colour bar gives γc for the colours.

#include "ui/SurfaceData.h"

#include <QWidget>

#include <memory>

class QLabel;
class QStackedWidget;
class QToolButton;
class QVBoxLayout;

namespace kinstab::ui {

class ColourBar;
class HeatMapView;

enum class SurfaceMode { Surface3D, Top, Map };

struct SurfaceGraph3D;

class SurfaceView : public QWidget {
    Q_OBJECT
public:
    explicit SurfaceView(QWidget* parent = nullptr);
    ~SurfaceView() override;

    // OpenGL is available (the 3D and top views can be chosen).
    bool is3D() const { return m_3d != nullptr; }
    // The GL window is what shows now (a screenshot must render it: grab() is blank).
    bool showsGL() const;
    SurfaceMode mode() const { return m_mode; }
    void setMode(SurfaceMode mode); // 3D modes fall back to the map without OpenGL
    // Grid lines on the 3D surface: on by default up to 60 × 60 points, where they help to
    // read the surface; beyond, they turn it into a dark sheet.
    bool wireframe() const { return m_wireframe; }
    void setWireframe(bool on);
    // The camera back to where it starts (the top view stays a top view).
    void resetView();
    ColourBar* colourBar() const { return m_bar; }
    HeatMapView* heatMap() const { return m_map; }
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
    using Graph3D = SurfaceGraph3D; // the Data Visualization objects (ui/SurfaceGraph3D.h)
    QWidget* buildToolBar();
    void build3D(); // m_3d->graph set
    void addNoticeLines(QVBoxLayout* layout);
    void buildStack();
    void updateLegend();
    void rebuildOverlays();
    void showPage();

    std::unique_ptr<Graph3D> m_3d;
    HeatMapView* m_map;
    QStackedWidget* m_stack;
    QLabel* m_hint;
    ColourBar* m_bar;
    QToolButton* m_buttons[3] = {};
    QToolButton* m_wireButton = nullptr;
    QToolButton* m_resetButton = nullptr;
    SurfaceMode m_mode = SurfaceMode::Surface3D;
    bool m_wireframe = true;
    QLabel* m_legend;
    QLabel* m_notice;
    QLabel* m_staleLine;
    bool m_stale = false;
    GammaGrid m_grid;
    SurfaceOverlays m_overlays;
    QPoint m_selected{-1, -1};
};

} // namespace kinstab::ui
