// SPDX-License-Identifier: GPL-3.0-or-later
// SurfaceView (ui/SurfaceView.h): the 3D graph, the data, overlays, legend and camera; the views
// and their tool bar in SurfaceViewModes.cpp.
#include "ui/SurfaceView.h"
#include "ui/SurfaceGraph3D.h"

#include "ui/ColourBar.h"
#include "ui/HeatMapView.h"
#include "ui/LegendEntry.h"
#include "ui/NiceTicks.h"
#include "ui/StaleFrame.h"

#include <QGuiApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QStackedWidget>
#include <QToolButton>
#include <QVBoxLayout>
#include <QtDataVisualization/Q3DCamera>
#include <QtDataVisualization/Q3DSurface>
#include <QtDataVisualization/Q3DTheme>
#include <QtDataVisualization/QCustom3DLabel>
#include <QtDataVisualization/QSurface3DSeries>
#include <QtDataVisualization/QSurfaceDataProxy>
#include <QtDataVisualization/QValue3DAxis>

#include <algorithm>
#include <cmath>
#include <limits>

namespace kinstab::ui {

namespace {
constexpr int kWireframeLimit = 60 * 60; // grid points up to which the wireframe is on
constexpr float kCameraX = -40.0f, kCameraY = 22.0f, kZoom = 80.0f;
// From straight above the axis labels stand outside the plot; at 100 % the A axis title fell
// off the bottom of a wide view (1920 x 1080). Top: the plot at 85 %, its titles inside.
constexpr float kTopZoom = 85.0f;
} // namespace

SurfaceView::SurfaceView(QWidget* parent)
    : QWidget(parent), m_map(new HeatMapView(this)), m_stack(new QStackedWidget(this)),
      m_hint(new QLabel(emptyHint(), this)), m_bar(new ColourBar(this)), m_legend(new QLabel(this)),
      m_notice(new QLabel(this)), m_staleLine(new QLabel(StaleFrame::staleText(), this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    addNoticeLines(layout);
    if (Q3DSurface* g = makeGraph()) {
        m_3d = std::make_unique<Graph3D>();
        m_3d->graph = g;
        build3D();
    } else {
        m_mode = SurfaceMode::Map;
    }
    layout->addWidget(buildToolBar());
    buildStack();
    auto* body = new QHBoxLayout;
    body->setContentsMargins(0, 0, 0, 0);
    body->addWidget(m_stack, 1);
    body->addWidget(m_bar);
    layout->addLayout(body, 1);
    // Wrapped between entries (never inside one): on one line each, the code ratios ran off
    // the right edge of a 1280 px window.
    m_legend->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    m_legend->setWordWrap(true);
    m_legend->setTextFormat(Qt::RichText);
    layout->addWidget(m_legend);
    showPage();
    updateLegend();
}

// The notice (a yellow band) and the stale line above the toolbar, both hidden until needed.
void SurfaceView::addNoticeLines(QVBoxLayout* layout) {
    m_notice->setWordWrap(true);
    m_notice->setContentsMargins(8, 6, 8, 6);
    m_notice->setStyleSheet(QStringLiteral("background: #fff4d6; color: #5a4300;"));
    m_notice->hide();
    layout->addWidget(m_notice);
    m_staleLine->setContentsMargins(8, 3, 8, 3);
    m_staleLine->setStyleSheet(StaleFrame::staleStyle());
    m_staleLine->hide();
    layout->addWidget(m_staleLine);
}

// The pages: the empty hint in large text, the 3D graph when there is one, the map; a point
// picked on the map is picked on the 3D surface too.
void SurfaceView::buildStack() {
    m_hint->setAlignment(Qt::AlignCenter);
    m_hint->setWordWrap(true);
    m_hint->setObjectName(QStringLiteral("emptyHint"));
    QFont big = m_hint->font();
    big.setPointSizeF(big.pointSizeF() * 1.3);
    m_hint->setFont(big);
    m_stack->addWidget(m_hint);
    if (m_3d) m_stack->addWidget(m_3d->container);
    m_stack->addWidget(m_map);
    connect(m_map, &HeatMapView::pointSelected, this, [this](int ai, int fi) {
        m_selected = QPoint(ai, fi);
        if (m_3d) m_3d->surface->setSelectedPoint(QPoint(fi, ai));
        emit pointSelected(ai, fi);
    });
}

void SurfaceView::build3D() {
    Q3DSurface* g = m_3d->graph;
    g->setShadowQuality(QAbstract3DGraph::ShadowQualityNone); // shadows dominate under software GL
    g->setSelectionMode(QAbstract3DGraph::SelectionItem);
    g->activeTheme()->setType(Q3DTheme::ThemeQt);
    g->activeTheme()->setLabelBackgroundEnabled(false);
    // Mostly ambient light, so the surface's colours stay those of the colour bar.
    g->activeTheme()->setAmbientLightStrength(0.55f);
    g->activeTheme()->setLightStrength(3.0f);
    QFont font = g->activeTheme()->font();
    font.setPointSize(44);
    g->activeTheme()->setFont(font);
    g->setAxisX(makeAxis(tr("A (g)"), QStringLiteral("%.2f")));
    g->setAxisY(makeAxis(m_grid.gammaTitle, QStringLiteral("%.2f")));
    g->setAxisZ(makeAxis(tr("f (Hz)"), QStringLiteral("%.2f")));
    g->scene()->activeCamera()->setCameraPosition(kCameraX, kCameraY, kZoom);
    g->setHorizontalAspectRatio(1.4f);
    m_3d->surface = new QSurface3DSeries;
    m_3d->surface->setDrawMode(QSurface3DSeries::DrawSurfaceAndWireframe);
    m_3d->surface->setWireframeColor(QColor(0, 0, 0, 90));
    m_3d->surface->setFlatShadingEnabled(false);
    m_3d->surface->setBaseGradient(surfaceGradient(false));
    m_3d->surface->setColorStyle(Q3DTheme::ColorStyleRangeGradient);
    m_3d->surface->setItemLabelVisible(false); // the linked charts name the picked point
    m_3d->surface->setItemLabelFormat(
        QStringLiteral("A = @xLabel g, f = @zLabel Hz, γc = @yLabel"));
    g->addSeries(m_3d->surface);
    m_3d->notComputed = makeOverlay(notComputedColor());
    m_3d->notComputed->setDrawMode(QSurface3DSeries::DrawSurfaceAndWireframe);
    m_3d->notComputed->setWireframeColor(QColor(120, 120, 120));
    g->addSeries(m_3d->notComputed);
    connect(m_3d->surface, &QSurface3DSeries::selectedPointChanged, this, [this](const QPoint& p) {
        if (p == QSurface3DSeries::invalidSelectionPosition()) return;
        const QPoint sel(p.y(), p.x()); // selectedPoint is (row = frequency, column = amplitude)
        if (sel == m_selected) return;
        m_selected = sel;
        m_map->setSelected(sel.x(), sel.y());
        emit pointSelected(sel.x(), sel.y());
    });
    m_3d->container = QWidget::createWindowContainer(g, this);
    m_3d->container->setMinimumSize(300, 250);
    m_3d->container->setFocusPolicy(Qt::StrongFocus);
    m_3d->container->setToolTip(tr("Drag with the right mouse button to rotate, wheel to zoom, "
                                   "left click a point to see its run."));
}

void SurfaceView::setWireframe(bool on) {
    m_wireframe = on;
    {
        const QSignalBlocker block(m_wireButton);
        m_wireButton->setChecked(on);
    }
    if (!m_3d) return;
    const auto mode =
        on ? QSurface3DSeries::DrawSurfaceAndWireframe : QSurface3DSeries::DrawSurface;
    m_3d->surface->setDrawMode(mode);
    m_3d->notComputed->setDrawMode(mode);
}

void SurfaceView::resetView() {
    if (!m_3d) return;
    Q3DCamera* camera = m_3d->graph->scene()->activeCamera();
    if (m_mode == SurfaceMode::Top)
        camera->setCameraPreset(Q3DCamera::CameraPresetDirectlyAbove);
    else
        camera->setCameraPosition(kCameraX, kCameraY, kZoom);
    camera->setZoomLevel(m_mode == SurfaceMode::Top ? kTopZoom : kZoom);
    camera->setTarget(QVector3D(0, 0, 0));
}

SurfaceView::~SurfaceView() = default;

QWidget* SurfaceView::graphWidget() const {
    return m_stack->currentWidget();
}

void SurfaceView::setData(const GammaGrid& g) {
    const bool newShape = g.amplitudes.size() != m_grid.amplitudes.size() ||
                          g.frequencies.size() != m_grid.frequencies.size();
    m_grid = g;
    m_map->setData(g);
    m_bar->setRange(colourScaleMaximum(g), g.gammaTitle);
    if (newShape) setWireframe(g.gamma.size() <= kWireframeLimit);
    showPage();
    if (!m_3d) {
        updateLegend();
        return;
    }
    if (g.empty()) { // New/Open: nothing computed for these inputs
        m_3d->surface->dataProxy()->resetArray(new QSurfaceDataArray);
        m_3d->notComputed->dataProxy()->resetArray(new QSurfaceDataArray);
        rebuildOverlays();
        updateLegend();
        return;
    }
    m_3d->graph->axisY()->setTitle(g.gammaTitle);
    std::vector<float> xs(g.amplitudes.begin(), g.amplitudes.end());
    std::vector<float> zs(g.frequencies.begin(), g.frequencies.end());
    const float nan = std::numeric_limits<float>::quiet_NaN();
    m_3d->surface->dataProxy()->resetArray(makeArray(zs, xs, [&](std::size_t r, std::size_t c) {
        return static_cast<float>(g.at(c, r)); // NaN (not yet computed) renders as a hole
    }));
    // The holes filled with a grey patch at 0, so "not computed" is seen, unlike stable.
    m_3d->notComputed->dataProxy()->resetArray(
        notComputedCount() == 0 ? new QSurfaceDataArray
                                : makeArray(zs, xs, [&](std::size_t r, std::size_t c) {
                                      return std::isfinite(g.at(c, r)) ? nan : 0.0f;
                                  }));
    rebuildOverlays();
    updateLegend();
    if (m_selected.x() >= 0)
        m_3d->surface->setSelectedPoint(QPoint(m_selected.y(), m_selected.x()));
}

void SurfaceView::setOverlays(const SurfaceOverlays& o) {
    m_overlays = o;
    m_map->setOverlays(o);
    if (m_3d) rebuildOverlays();
    updateLegend();
}

void SurfaceView::selectPoint(int ai, int fi) {
    m_map->setSelected(ai, fi);
    if (!m_3d) {
        m_selected = QPoint(ai, fi);
        emit pointSelected(ai, fi);
        return;
    }
    m_3d->surface->setSelectedPoint(QPoint(fi, ai));
}

QImage SurfaceView::renderImage(QSize size) {
    if (!showsGL()) {
        const QSize old = m_map->size();
        m_map->resize(size);
        QImage img = m_map->grab().toImage();
        m_map->resize(old);
        return img;
    }
    return m_3d->graph->renderToImage(4, size);
}

void SurfaceView::rebuildOverlays() {
    drawOverlays3D(*m_3d, m_grid, m_overlays);
}

void SurfaceView::updateLegend() {
    auto swatch = [](const QColor& c, const QString& text) {
        return legendEntryHtml(c, text, QStringLiteral("; font-size:large")) +
               QStringLiteral("&nbsp;&nbsp; ");
    };
    // The γc colours are read off the colour bar; the legend names the lines drawn over them.
    QString html = swatch(gammaColor(0.0), tr("stable (γc = 0)"));
    if (const int n = notComputedCount(); n > 0)
        html += swatch(notComputedColor(), tr("not computed (%1 points)").arg(n));
    if (m_overlays.buildingFrequency)
        html +=
            swatch(Qt::black,
                   tr("building f = 1/T = %1 Hz").arg(*m_overlays.buildingFrequency, 0, 'f', 3));
    if (!m_overlays.aCrit.empty())
        html += swatch(QColor(160, 160, 160), tr("A_crit(f) (white line)"));
    html += QStringLiteral("<br>") + tr("Top-floor ratios F_top/w_top: ");
    for (const CodeRatio& c : m_overlays.codes) {
        const bool off = !m_grid.empty() && (c.ratio < m_grid.amplitudes.front() ||
                                             c.ratio > m_grid.amplitudes.back());
        html += swatch(c.color, (off ? tr("%1 %2 g (outside the grid)") : tr("%1 %2 g"))
                                    .arg(c.name)
                                    .arg(c.ratio, 0, 'f', 3));
    }
    m_legend->setText(html);
}

int SurfaceView::notComputedCount() const {
    int n = 0;
    for (double v : m_grid.gamma)
        n += !std::isfinite(v);
    return n;
}

QString SurfaceView::legendText() const {
    return m_legend->text();
}

void SurfaceView::setStale(bool stale) {
    m_stale = stale;
    m_staleLine->setVisible(stale);
    m_map->setStale(stale);
    m_bar->setFaded(stale);
    if (m_3d) m_3d->surface->setBaseGradient(surfaceGradient(stale));
}

void SurfaceView::setNotice(const QString& text) {
    m_notice->setText(text);
    m_notice->setVisible(!text.isEmpty());
}

QString SurfaceView::notice() const {
    return m_notice->text();
}

} // namespace kinstab::ui
