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

void drawOverlays3D(SurfaceGraph3D& g3, const GammaGrid& grid, const SurfaceOverlays& overlays) {
    Q3DSurface* g = g3.graph;
    for (QSurface3DSeries* s : g3.overlays) {
        g->removeSeries(s);
        delete s;
    }
    g3.overlays.clear();
    g->removeCustomItems();
    if (grid.empty()) return;

    // Axes fit the grid (widened to whole 1-2-5 steps); code ratios and the building's frequency
    // are drawn only where they fall on the surface, the legend lists the others.
    // The f axis runs into the depth, foreshortened: at 10 ticks its labels ran into each other
    // (0.5 0.6 0.7 ... at a 1280 px window); 5 keep them apart, 6 for A across the front.
    const NiceAxis ax = niceAxis(grid.amplitudes.front(), grid.amplitudes.back(), 6);
    const NiceAxis fx = niceAxis(grid.frequencies.front(), grid.frequencies.back(), 5);
    const float yMax = static_cast<float>(colourScaleMaximum(grid));
    const NiceAxis yx = niceAxis(0, yMax, 6);
    auto apply = [](QValue3DAxis* axis, const NiceAxis& n) {
        axis->setRange(static_cast<float>(n.min), static_cast<float>(n.max));
        axis->setSegmentCount(n.segments());
        axis->setSubSegmentCount(1);
        axis->setLabelFormat(QStringLiteral("%.%1f").arg(n.decimals()));
    };
    apply(g->axisX(), ax);
    apply(g->axisZ(), fx);
    apply(g->axisY(), yx);
    const float aMin = static_cast<float>(ax.min), aMax = static_cast<float>(ax.max);
    const float fMin = static_cast<float>(fx.min), fMax = static_cast<float>(fx.max);
    auto onGrid = [&](double a) {
        return a >= grid.amplitudes.front() && a <= grid.amplitudes.back();
    };
    const float lift = 0.012f * yMax; // above the surface, so the overlay does not z-fight
    const float wa = 0.004f * (aMax - aMin), wf = 0.006f * (fMax - fMin);
    std::vector<float> zs(grid.frequencies.begin(), grid.frequencies.end());
    auto heightAt = [&](std::size_t fi, double a) {
        const double v = gammaAtAmplitude(grid, fi, a);
        return static_cast<float>(std::isfinite(v) ? v : 0.0) + lift;
    };
    auto add = [&](QSurface3DSeries* s, QSurfaceDataArray* array) {
        s->dataProxy()->resetArray(array);
        g->addSeries(s);
        g3.overlays.push_back(s);
    };
    for (const CodeRatio& c : overlays.codes) {
        if (!onGrid(c.ratio)) continue;
        const float a = static_cast<float>(c.ratio);
        add(makeOverlay(c.color), makeArray(zs, {a - wa, a + wa}, [&](std::size_t r, std::size_t) {
                return heightAt(r, c.ratio);
            }));
    }
    if (overlays.buildingFrequency && *overlays.buildingFrequency >= grid.frequencies.front() &&
        *overlays.buildingFrequency <= grid.frequencies.back()) {
        const double fb = *overlays.buildingFrequency;
        const std::size_t fi = nearestFrequency(grid, fb);
        std::vector<float> xs(grid.amplitudes.begin(), grid.amplitudes.end());
        const float f = static_cast<float>(fb);
        add(makeOverlay(Qt::black),
            makeArray({f - wf, f + wf}, xs,
                      [&](std::size_t, std::size_t c) { return heightAt(fi, xs[c]); }));
        for (std::size_t k = 0; k < overlays.codes.size(); ++k) {
            const CodeRatio& c = overlays.codes[k];
            if (!onGrid(c.ratio)) continue;
            const float stagger = (0.10f + 0.09f * static_cast<float>(k)) * yMax; // close ratios
            auto* label = new QCustom3DLabel(
                QStringLiteral("%1 %2").arg(c.name).arg(c.ratio, 0, 'f', 2),
                g->activeTheme()->font(),
                QVector3D(static_cast<float>(c.ratio), heightAt(fi, c.ratio) + stagger, f),
                QVector3D(1.1f, 1.1f, 0.0f), QQuaternion()); // about the axis labels' size
            label->setFacingCamera(true);
            label->setTextColor(c.color.darker(130));
            label->setBorderEnabled(false);
            label->setBackgroundEnabled(false);
            g->addCustomItem(label);
        }
    }
    // A_crit(f) where it lies on the grid: the renderer crashes (Qt 6.4) on a strip that
    // leaves the axis range, and the axes no longer stretch to hold it.
    std::vector<std::pair<double, double>> crit;
    for (const auto& fa : overlays.aCrit)
        if (onGrid(fa.second) && fa.first >= grid.frequencies.front() &&
            fa.first <= grid.frequencies.back())
            crit.push_back(fa);
    if (crit.size() >= 2) {
        // Columns of this strip are not straight (A_crit varies with f); it is two points wide.
        auto* array = new QSurfaceDataArray;
        for (const auto& [f, a] : crit) {
            // On the surface's rising wall, where gamma_c leaves 0.
            const float y = heightAt(nearestFrequency(grid, f), a);
            const float x = static_cast<float>(a), z = static_cast<float>(f);
            auto* row = new QSurfaceDataRow(2);
            (*row)[0].setPosition(QVector3D(std::max(aMin, x - wa), y, z));
            (*row)[1].setPosition(QVector3D(std::min(aMax, x + wa), y, z));
            array->append(row);
        }
        add(makeOverlay(QColor(250, 250, 250)), array);
    }
}

} // namespace kinstab::ui
