// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/SurfaceGraph3D.h"

#include "ui/ColourBar.h"
#include "ui/NiceTicks.h"

#include <QButtonGroup>
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

// A Q3DSurface needs a real OpenGL context: the offscreen platform crashes even when it
// reports one (measured with Qt 6.4 on Debian 12), so it is not even tried there.
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

namespace {

// The fitted axes and the sizes the overlays are drawn with.
struct OverlayFrame {
    const GammaGrid& grid;
    float yMax = 0, aMin = 0, aMax = 0, fMin = 0, fMax = 0;
    float lift = 0;       // above the surface, so the overlay does not z-fight
    float wa = 0, wf = 0; // the strips' half widths along A and f

    bool onGridA(double a) const {
        return a >= grid.amplitudes.front() && a <= grid.amplitudes.back();
    }
    bool onGridF(double f) const {
        return f >= grid.frequencies.front() && f <= grid.frequencies.back();
    }
    float heightAt(std::size_t fi, double a) const {
        const double v = gammaAtAmplitude(grid, fi, a);
        return static_cast<float>(std::isfinite(v) ? v : 0.0) + lift;
    }
};

void removeOverlays(SurfaceGraph3D& g3) {
    for (QSurface3DSeries* s : g3.overlays) {
        g3.graph->removeSeries(s);
        delete s;
    }
    g3.overlays.clear();
    g3.graph->removeCustomItems();
}

void applyNiceAxis(QValue3DAxis* axis, const NiceAxis& n) {
    axis->setRange(static_cast<float>(n.min), static_cast<float>(n.max));
    axis->setSegmentCount(n.segments());
    axis->setSubSegmentCount(1);
    axis->setLabelFormat(QStringLiteral("%.%1f").arg(n.decimals()));
}

// Axes fit the grid (widened to whole 1-2-5 steps).
// The f axis runs into the depth, foreshortened: at 10 ticks its labels ran into each other
// (0.5 0.6 0.7 ... at a 1280 px window); 5 keep them apart, 6 for A across the front.
OverlayFrame fitAxes(Q3DSurface* g, const GammaGrid& grid) {
    const NiceAxis ax = niceAxis(grid.amplitudes.front(), grid.amplitudes.back(), 6);
    const NiceAxis fx = niceAxis(grid.frequencies.front(), grid.frequencies.back(), 5);
    const float yMax = static_cast<float>(colourScaleMaximum(grid));
    applyNiceAxis(g->axisX(), ax);
    applyNiceAxis(g->axisZ(), fx);
    applyNiceAxis(g->axisY(), niceAxis(0, yMax, 6));
    OverlayFrame fr{grid};
    fr.yMax = yMax;
    fr.aMin = static_cast<float>(ax.min), fr.aMax = static_cast<float>(ax.max);
    fr.fMin = static_cast<float>(fx.min), fr.fMax = static_cast<float>(fx.max);
    fr.lift = 0.012f * yMax;
    fr.wa = 0.004f * (fr.aMax - fr.aMin), fr.wf = 0.006f * (fr.fMax - fr.fMin);
    return fr;
}

void addOverlay(SurfaceGraph3D& g3, QSurface3DSeries* s, QSurfaceDataArray* array) {
    s->dataProxy()->resetArray(array);
    g3.graph->addSeries(s);
    g3.overlays.push_back(s);
}

// One narrow strip along f at each code ratio on the grid.
void addCodeStrips(SurfaceGraph3D& g3, const OverlayFrame& fr,
                   const std::vector<CodeRatio>& codes) {
    const std::vector<float> zs(fr.grid.frequencies.begin(), fr.grid.frequencies.end());
    for (const CodeRatio& c : codes) {
        if (!fr.onGridA(c.ratio)) continue;
        const float a = static_cast<float>(c.ratio);
        addOverlay(g3, makeOverlay(c.color),
                   makeArray(zs, {a - fr.wa, a + fr.wa},
                             [&](std::size_t r, std::size_t) { return fr.heightAt(r, c.ratio); }));
    }
}

// The code ratios named where they cross the building's frequency, staggered upwards so close
// ratios do not overlap.
void addCodeLabels(Q3DSurface* g, const OverlayFrame& fr, const std::vector<CodeRatio>& codes,
                   std::size_t fi, float f) {
    for (std::size_t k = 0; k < codes.size(); ++k) {
        const CodeRatio& c = codes[k];
        if (!fr.onGridA(c.ratio)) continue;
        const float stagger = (0.10f + 0.09f * static_cast<float>(k)) * fr.yMax;
        auto* label = new QCustom3DLabel(
            QStringLiteral("%1 %2").arg(c.name).arg(c.ratio, 0, 'f', 2), g->activeTheme()->font(),
            QVector3D(static_cast<float>(c.ratio), fr.heightAt(fi, c.ratio) + stagger, f),
            QVector3D(1.1f, 1.1f, 0.0f), QQuaternion()); // about the axis labels' size
        label->setFacingCamera(true);
        label->setTextColor(c.color.darker(130));
        label->setBorderEnabled(false);
        label->setBackgroundEnabled(false);
        g->addCustomItem(label);
    }
}

// A black strip along A at the building's frequency, with the code ratios' labels on it.
void addBuildingStrip(SurfaceGraph3D& g3, const OverlayFrame& fr, double fb,
                      const std::vector<CodeRatio>& codes) {
    const std::size_t fi = nearestFrequency(fr.grid, fb);
    const std::vector<float> xs(fr.grid.amplitudes.begin(), fr.grid.amplitudes.end());
    const float f = static_cast<float>(fb);
    addOverlay(g3, makeOverlay(Qt::black),
               makeArray({f - fr.wf, f + fr.wf}, xs,
                         [&](std::size_t, std::size_t c) { return fr.heightAt(fi, xs[c]); }));
    addCodeLabels(g3.graph, fr, codes, fi, f);
}

// A_crit(f) where it lies on the grid: the renderer crashes (Qt 6.4) on a strip that leaves the
// axis range, and the axes no longer stretch to hold it.
void addCritStrip(SurfaceGraph3D& g3, const OverlayFrame& fr,
                  const std::vector<std::pair<double, double>>& aCrit) {
    std::vector<std::pair<double, double>> crit;
    for (const auto& fa : aCrit)
        if (fr.onGridA(fa.second) && fr.onGridF(fa.first)) crit.push_back(fa);
    if (crit.size() < 2) return;
    // Columns of this strip are not straight (A_crit varies with f); it is two points wide.
    auto* array = new QSurfaceDataArray;
    for (const auto& [f, a] : crit) {
        // On the surface's rising wall, where gamma_c leaves 0.
        const float y = fr.heightAt(nearestFrequency(fr.grid, f), a);
        const float x = static_cast<float>(a), z = static_cast<float>(f);
        auto* row = new QSurfaceDataRow(2);
        (*row)[0].setPosition(QVector3D(std::max(fr.aMin, x - fr.wa), y, z));
        (*row)[1].setPosition(QVector3D(std::min(fr.aMax, x + fr.wa), y, z));
        array->append(row);
    }
    addOverlay(g3, makeOverlay(QColor(250, 250, 250)), array);
}

} // namespace

// Code ratios and the building's frequency are drawn only where they fall on the surface, the
// legend lists the others.
void drawOverlays3D(SurfaceGraph3D& g3, const GammaGrid& grid, const SurfaceOverlays& overlays) {
    removeOverlays(g3);
    if (grid.empty()) return;
    const OverlayFrame fr = fitAxes(g3.graph, grid);
    addCodeStrips(g3, fr, overlays.codes);
    if (overlays.buildingFrequency && fr.onGridF(*overlays.buildingFrequency))
        addBuildingStrip(g3, fr, *overlays.buildingFrequency, overlays.codes);
    addCritStrip(g3, fr, overlays.aCrit);
}

} // namespace kinstab::ui
