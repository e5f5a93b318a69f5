// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/SurfaceView.h"

#include "ui/HeatMapView.h"
#include "ui/StaleFrame.h"

#include <QGuiApplication>
#include <QLabel>
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

struct SurfaceView::Graph3D {
    Q3DSurface* graph = nullptr; // owned by the window container
    QWidget* container = nullptr;
    QSurface3DSeries* surface = nullptr;
    QSurface3DSeries* notComputed = nullptr; // grey patches at γc = 0 where no point was run
    std::vector<QSurface3DSeries*> overlays;
};

namespace {

// A Q3DSurface needs a real OpenGL context: the offscreen platform crashes even when it
// reports one (QT-NOTES §2.2), so it is not even tried there.
Q3DSurface* makeGraph() {
    if (QGuiApplication::platformName() == QLatin1String("offscreen")) return nullptr;
    auto* g = new Q3DSurface;
    if (g->hasContext()) return g;
    delete g;
    return nullptr;
}

QValue3DAxis* makeAxis(const QString& title, const QString& format) {
    auto* a = new QValue3DAxis;
    a->setTitle(title);
    a->setTitleVisible(true);
    a->setLabelFormat(format);
    a->setLabelAutoRotation(30);
    return a;
}

// Owns nothing on return: resetArray takes the rows.
QSurfaceDataArray* makeArray(const std::vector<float>& zs, const std::vector<float>& xs,
                             const std::function<float(std::size_t, std::size_t)>& y) {
    auto* array = new QSurfaceDataArray;
    array->reserve(static_cast<qsizetype>(zs.size()));
    for (std::size_t r = 0; r < zs.size(); ++r) {
        auto* row = new QSurfaceDataRow(static_cast<qsizetype>(xs.size()));
        for (std::size_t c = 0; c < xs.size(); ++c)
            (*row)[static_cast<qsizetype>(c)].setPosition(QVector3D(xs[c], y(r, c), zs[r]));
        array->append(row);
    }
    return array;
}

QLinearGradient surfaceGradient(bool faded) {
    QLinearGradient gradient;
    for (double t : {0.0, 1.0 / 3, 2.0 / 3, 1.0}) {
        const QColor c = gammaColor(t);
        // Faded: two thirds of the way to white, so a stale surface cannot pass for a result.
        gradient.setColorAt(t, faded ? QColor((c.red() + 2 * 255) / 3, (c.green() + 2 * 255) / 3,
                                              (c.blue() + 2 * 255) / 3)
                                     : c);
    }
    return gradient;
}

QSurface3DSeries* makeOverlay(const QColor& color) {
    auto* s = new QSurface3DSeries;
    s->setDrawMode(QSurface3DSeries::DrawSurface);
    s->setFlatShadingEnabled(false);
    s->setColorStyle(Q3DTheme::ColorStyleUniform);
    s->setBaseColor(color);
    s->setItemLabelVisible(false);
    return s;
}

} // namespace

SurfaceView::SurfaceView(QWidget* parent)
    : QWidget(parent), m_legend(new QLabel(this)), m_notice(new QLabel(this)),
      m_staleLine(new QLabel(StaleFrame::staleText(), this)) {
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_notice->setWordWrap(true);
    m_notice->setContentsMargins(8, 6, 8, 6);
    m_notice->setStyleSheet(QStringLiteral("background: #fff4d6; color: #5a4300;"));
    m_notice->hide();
    layout->addWidget(m_notice);
    m_staleLine->setContentsMargins(8, 3, 8, 3);
    m_staleLine->setStyleSheet(StaleFrame::staleStyle());
    m_staleLine->hide();
    layout->addWidget(m_staleLine);
    if (Q3DSurface* g = makeGraph()) {
        m_3d = std::make_unique<Graph3D>();
        m_3d->graph = g;
        g->setShadowQuality(
            QAbstract3DGraph::ShadowQualityNone); // shadows dominate under software GL
        g->setSelectionMode(QAbstract3DGraph::SelectionItem);
        g->activeTheme()->setType(Q3DTheme::ThemeQt);
        g->activeTheme()->setLabelBackgroundEnabled(false);
        QFont font = g->activeTheme()->font();
        font.setPointSize(44);
        g->activeTheme()->setFont(font);
        g->setAxisX(makeAxis(tr("A (g)"), QStringLiteral("%.2f")));
        g->setAxisY(makeAxis(m_grid.gammaTitle, QStringLiteral("%.2f")));
        g->setAxisZ(makeAxis(tr("f (Hz)"), QStringLiteral("%.2f")));
        g->scene()->activeCamera()->setCameraPosition(-40.0f, 22.0f, 80.0f);
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
        connect(m_3d->surface, &QSurface3DSeries::selectedPointChanged, this,
                [this](const QPoint& p) {
                    if (p == QSurface3DSeries::invalidSelectionPosition()) return;
                    const QPoint sel(
                        p.y(), p.x()); // selectedPoint is (row = frequency, column = amplitude)
                    if (sel == m_selected) return;
                    m_selected = sel;
                    emit pointSelected(sel.x(), sel.y());
                });
        m_3d->container = QWidget::createWindowContainer(g, this);
        m_3d->container->setMinimumSize(300, 250);
        m_3d->container->setFocusPolicy(Qt::StrongFocus);
        m_3d->container->setToolTip(tr("Drag with the right mouse button to rotate, wheel to zoom, "
                                       "left click a point to see its run."));
        layout->addWidget(m_3d->container, 1);
    } else {
        m_map = new HeatMapView(this);
        connect(m_map, &HeatMapView::pointSelected, this, [this](int ai, int fi) {
            m_selected = QPoint(ai, fi);
            emit pointSelected(ai, fi);
        });
        layout->addWidget(m_map, 1);
    }
    // No word wrap: a wrapped label's minimum height would stretch the window; two fixed lines.
    m_legend->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
    m_legend->setTextFormat(Qt::RichText);
    layout->addWidget(m_legend);
    updateLegend();
}

SurfaceView::~SurfaceView() = default;

QWidget* SurfaceView::graphWidget() const {
    return m_3d ? m_3d->container : static_cast<QWidget*>(m_map);
}

void SurfaceView::setData(const GammaGrid& g) {
    m_grid = g;
    if (m_map) {
        m_map->setData(g);
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
    // A wireframe over thousands of cells is a black sheet that hides the colours.
    const auto mode = g.gamma.size() > 2500 ? QSurface3DSeries::DrawSurface
                                            : QSurface3DSeries::DrawSurfaceAndWireframe;
    m_3d->surface->setDrawMode(mode);
    m_3d->notComputed->setDrawMode(mode);
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
    if (m_map)
        m_map->setOverlays(o);
    else
        rebuildOverlays();
    updateLegend();
}

void SurfaceView::selectPoint(int ai, int fi) {
    if (m_map) {
        m_map->setSelected(ai, fi);
        m_selected = QPoint(ai, fi);
        emit pointSelected(ai, fi);
        return;
    }
    m_3d->surface->setSelectedPoint(QPoint(fi, ai));
}

QImage SurfaceView::renderImage(QSize size) {
    if (m_map) {
        const QSize old = m_map->size();
        m_map->resize(size);
        QImage img = m_map->grab().toImage();
        m_map->resize(old);
        return img;
    }
    return m_3d->graph->renderToImage(4, size);
}

void SurfaceView::rebuildOverlays() {
    Q3DSurface* g = m_3d->graph;
    for (QSurface3DSeries* s : m_3d->overlays) {
        g->removeSeries(s);
        delete s;
    }
    m_3d->overlays.clear();
    g->removeCustomItems();
    if (m_grid.empty()) return;

    // Axis ranges: the grid, widened to show code ratios and the building's frequency.
    float aMin = static_cast<float>(m_grid.amplitudes.front()),
          aMax = static_cast<float>(m_grid.amplitudes.back());
    float fMin = static_cast<float>(m_grid.frequencies.front()),
          fMax = static_cast<float>(m_grid.frequencies.back());
    for (const CodeRatio& c : m_overlays.codes)
        aMin = std::min(aMin, static_cast<float>(0.9 * c.ratio));
    if (m_overlays.buildingFrequency) {
        fMin = std::min(fMin, static_cast<float>(*m_overlays.buildingFrequency));
        fMax = std::max(fMax, static_cast<float>(*m_overlays.buildingFrequency));
    }
    if (aMax <= aMin) aMax = aMin + 0.1f;
    if (fMax <= fMin) fMax = fMin + 0.1f;
    double gMax = 0;
    for (double v : m_grid.gamma)
        if (std::isfinite(v)) gMax = std::max(gMax, v);
    const float yMax = static_cast<float>(gMax > 0 ? 1.05 * gMax : 1.0);
    g->axisX()->setRange(aMin, aMax);
    g->axisZ()->setRange(fMin, fMax);
    g->axisY()->setRange(0, yMax);

    const float lift = 0.012f * yMax; // above the surface, so the overlay does not z-fight
    const float wa = 0.004f * (aMax - aMin), wf = 0.006f * (fMax - fMin);
    std::vector<float> zs(m_grid.frequencies.begin(), m_grid.frequencies.end());
    auto heightAt = [&](std::size_t fi, double a) {
        const double v = gammaAtAmplitude(m_grid, fi, a);
        return static_cast<float>(std::isfinite(v) ? v : 0.0) + lift;
    };
    auto add = [&](QSurface3DSeries* s, QSurfaceDataArray* array) {
        s->dataProxy()->resetArray(array);
        g->addSeries(s);
        m_3d->overlays.push_back(s);
    };
    for (const CodeRatio& c : m_overlays.codes) {
        const float a = static_cast<float>(c.ratio);
        add(makeOverlay(c.color), makeArray(zs, {a - wa, a + wa}, [&](std::size_t r, std::size_t) {
                return heightAt(r, c.ratio);
            }));
    }
    if (m_overlays.buildingFrequency) {
        const double fb = *m_overlays.buildingFrequency;
        const std::size_t fi = nearestFrequency(m_grid, fb);
        std::vector<float> xs;
        if (aMin < m_grid.amplitudes.front()) xs.push_back(aMin);
        xs.insert(xs.end(), m_grid.amplitudes.begin(), m_grid.amplitudes.end());
        const float f = static_cast<float>(fb);
        add(makeOverlay(Qt::black),
            makeArray({f - wf, f + wf}, xs,
                      [&](std::size_t, std::size_t c) { return heightAt(fi, xs[c]); }));
        for (std::size_t k = 0; k < m_overlays.codes.size(); ++k) {
            const CodeRatio& c = m_overlays.codes[k];
            const float stagger = (0.10f + 0.09f * static_cast<float>(k)) * yMax; // close ratios
            auto* label = new QCustom3DLabel(
                QStringLiteral("%1 %2").arg(c.name).arg(c.ratio, 0, 'f', 2),
                g->activeTheme()->font(),
                QVector3D(static_cast<float>(c.ratio), heightAt(fi, c.ratio) + stagger, f),
                QVector3D(0.45f, 0.45f, 0.0f), QQuaternion());
            label->setFacingCamera(true);
            label->setTextColor(c.color.darker(130));
            label->setBorderEnabled(false);
            label->setBackgroundEnabled(false);
            g->addCustomItem(label);
        }
    }
    if (m_overlays.aCrit.size() >= 2) {
        std::vector<float> cz, ca;
        for (const auto& [f, a] : m_overlays.aCrit) {
            cz.push_back(static_cast<float>(f));
            ca.push_back(static_cast<float>(a));
        }
        // Columns of this strip are not straight (A_crit varies with f); it is two points wide.
        auto* array = new QSurfaceDataArray;
        for (std::size_t r = 0; r < cz.size(); ++r) {
            // On the surface's rising wall, where gamma_c leaves 0.
            const float y = heightAt(nearestFrequency(m_grid, m_overlays.aCrit[r].first),
                                     m_overlays.aCrit[r].second);
            auto* row = new QSurfaceDataRow(2);
            (*row)[0].setPosition(QVector3D(ca[r] - wa, y, cz[r]));
            (*row)[1].setPosition(QVector3D(ca[r] + wa, y, cz[r]));
            array->append(row);
        }
        add(makeOverlay(QColor(250, 250, 250)), array);
    }
}

void SurfaceView::updateLegend() {
    auto swatch = [](const QColor& c, const QString& text) {
        return QStringLiteral(
                   "<span style='color:%1; font-size:large'>&#9632;</span>&nbsp;%2&nbsp;&nbsp; ")
            .arg(c.name(), text);
    };
    QString html = swatch(gammaColor(0.0), tr("stable (γc = 0)")) +
                   swatch(gammaColor(1.0), tr("fastest collapse (largest γc)"));
    if (const int n = notComputedCount(); n > 0)
        html += swatch(notComputedColor(), tr("not computed (%1 points)").arg(n));
    if (m_overlays.buildingFrequency)
        html +=
            swatch(Qt::black,
                   tr("building f = 1/T = %1 Hz").arg(*m_overlays.buildingFrequency, 0, 'f', 3));
    if (!m_overlays.aCrit.empty())
        html += swatch(QColor(160, 160, 160), tr("A_crit(f) (white line)"));
    html += QStringLiteral("<br>") + tr("Top-floor ratios F_top/w_top: ");
    for (const CodeRatio& c : m_overlays.codes)
        html += swatch(c.color, tr("%1 %2 g").arg(c.name).arg(c.ratio, 0, 'f', 3));
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
    if (m_map)
        m_map->setStale(stale);
    else
        m_3d->surface->setBaseGradient(surfaceGradient(stale));
}

void SurfaceView::setNotice(const QString& text) {
    m_notice->setText(text);
    m_notice->setVisible(!text.isEmpty());
}

QString SurfaceView::notice() const {
    return m_notice->text();
}

} // namespace kinstab::ui
