// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/HeatMapView.h"

#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace kinstab::ui {

QColor gammaColor(double t) {
    // Stable (0) dark blue, then through teal and yellow to red at the largest γc.
    static const QColor stops[] = {QColor(40, 60, 140), QColor(30, 150, 160), QColor(240, 220, 60),
                                   QColor(215, 50, 40)};
    t = std::clamp(t, 0.0, 1.0) * 3.0;
    const int i = std::min(static_cast<int>(t), 2);
    const double u = t - i;
    auto mix = [&](int a, int b) { return static_cast<int>(a + (b - a) * u); };
    return QColor(mix(stops[i].red(), stops[i + 1].red()),
                  mix(stops[i].green(), stops[i + 1].green()),
                  mix(stops[i].blue(), stops[i + 1].blue()));
}

QColor notComputedColor() {
    return QColor(205, 205, 205);
}

HeatMapView::HeatMapView(QWidget* parent) : QWidget(parent) {
    setMinimumSize(300, 250);
    setToolTip(tr("γc(A, f) as a colour map (OpenGL is not available for the 3D view). Click a "
                  "cell to see that run."));
}

void HeatMapView::setData(const GammaGrid& g) {
    m_grid = g;
    updateRanges();
    update();
}

void HeatMapView::setOverlays(const SurfaceOverlays& o) {
    m_overlays = o;
    updateRanges();
    update();
}

void HeatMapView::setStale(bool stale) {
    m_stale = stale;
    update();
}

void HeatMapView::setSelected(int ai, int fi) {
    m_selA = ai;
    m_selF = fi;
    update();
}

void HeatMapView::updateRanges() {
    if (m_grid.empty()) return;
    m_aMin = m_grid.amplitudes.front();
    m_aMax = m_grid.amplitudes.back();
    for (const CodeRatio& c : m_overlays.codes)
        m_aMin = std::min(m_aMin, 0.9 * c.ratio);
    m_fMin = m_grid.frequencies.front();
    m_fMax = m_grid.frequencies.back();
    if (m_aMax <= m_aMin) m_aMax = m_aMin + 1;
    if (m_fMax <= m_fMin) m_fMax = m_fMin + 1;
    m_gMax = 0;
    for (double g : m_grid.gamma)
        if (std::isfinite(g)) m_gMax = std::max(m_gMax, g);
    if (m_gMax <= 0) m_gMax = 1;
}

QRectF HeatMapView::plotRect() const {
    return QRectF(60, 12, width() - 130, height() - 58);
}

double HeatMapView::xOf(double a) const {
    const QRectF r = plotRect();
    return r.left() + (a - m_aMin) / (m_aMax - m_aMin) * r.width();
}

double HeatMapView::yOf(double f) const {
    const QRectF r = plotRect();
    return r.bottom() - (f - m_fMin) / (m_fMax - m_fMin) * r.height();
}

void HeatMapView::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), palette().base());
    if (m_grid.empty()) {
        p.drawText(rect(), Qt::AlignCenter, tr("Press Run to compute the γc surface"));
        return;
    }
    p.setRenderHint(QPainter::Antialiasing);
    paintCells(p);
    paintOverlays(p);
    paintAxes(p);
    if (m_stale) p.fillRect(rect(), QColor(255, 255, 255, 165)); // dimmed, still readable
}

void HeatMapView::paintCells(QPainter& p) const {
    const auto& as = m_grid.amplitudes;
    const auto& fs = m_grid.frequencies;
    // One pixel per grid point, scaled up without smoothing: thousands of antialiased
    // rectangles would take tens of milliseconds per repaint during a sweep.
    QImage cells(static_cast<int>(as.size()), static_cast<int>(fs.size()), QImage::Format_RGB32);
    for (std::size_t i = 0; i < as.size(); ++i)
        for (std::size_t j = 0; j < fs.size(); ++j) {
            const double g = m_grid.at(i, j);
            const QColor c = std::isfinite(g) ? gammaColor(g / m_gMax) : notComputedColor();
            cells.setPixel(static_cast<int>(i), static_cast<int>(fs.size() - 1 - j), c.rgb());
        }
    // Cell edges half a step beyond the first and last grid values (uniform grids).
    auto half = [](const std::vector<double>& v) {
        return v.size() > 1 ? 0.5 * (v[1] - v[0]) : 0.025;
    };
    const QRectF target(QPointF(xOf(as.front() - half(as)), yOf(fs.back() + half(fs))),
                        QPointF(xOf(as.back() + half(as)), yOf(fs.front() - half(fs))));
    p.save();
    p.setClipRect(plotRect());
    p.setRenderHint(QPainter::SmoothPixmapTransform, false);
    p.drawImage(target, cells);
    p.restore();
    if (m_selA >= 0 && m_selF >= 0 && static_cast<std::size_t>(m_selA) < as.size() &&
        static_cast<std::size_t>(m_selF) < fs.size()) {
        p.setPen(QPen(Qt::white, 2));
        p.setBrush(Qt::NoBrush);
        p.drawEllipse(QPointF(xOf(as[static_cast<std::size_t>(m_selA)]),
                              yOf(fs[static_cast<std::size_t>(m_selF)])),
                      6, 6);
    }
}

void HeatMapView::paintOverlays(QPainter& p) const {
    const QRectF r = plotRect();
    p.save();
    p.setClipRect(r);
    for (const CodeRatio& c : m_overlays.codes) {
        p.setPen(QPen(c.color, 2.5, Qt::DashLine));
        p.drawLine(QPointF(xOf(c.ratio), r.top()), QPointF(xOf(c.ratio), r.bottom()));
    }
    if (m_overlays.buildingFrequency) {
        p.setPen(QPen(Qt::black, 2, Qt::DotLine));
        const double y = yOf(*m_overlays.buildingFrequency);
        p.drawLine(QPointF(r.left(), y), QPointF(r.right(), y));
        for (const CodeRatio& c : m_overlays.codes) {
            p.setPen(QPen(Qt::black, 1.5));
            p.setBrush(c.color);
            p.drawEllipse(QPointF(xOf(c.ratio), y), 5, 5);
        }
    }
    if (!m_overlays.aCrit.empty()) {
        QPainterPath path;
        path.moveTo(xOf(m_overlays.aCrit.front().second), yOf(m_overlays.aCrit.front().first));
        for (const auto& [f, a] : m_overlays.aCrit)
            path.lineTo(xOf(a), yOf(f));
        p.setPen(QPen(Qt::white, 2.5));
        p.setBrush(Qt::NoBrush);
        p.drawPath(path);
    }
    p.restore();
}

void HeatMapView::paintAxes(QPainter& p) const {
    const QRectF r = plotRect();
    p.setPen(palette().text().color());
    p.setBrush(Qt::NoBrush);
    p.drawRect(r);
    const QFontMetrics fm(font());
    for (int k = 0; k <= 5; ++k) {
        const double a = m_aMin + (m_aMax - m_aMin) * k / 5;
        const double f = m_fMin + (m_fMax - m_fMin) * k / 5;
        const QString as = QString::number(a, 'f', 2), fs = QString::number(f, 'f', 2);
        p.drawText(QPointF(xOf(a) - fm.horizontalAdvance(as) / 2.0, r.bottom() + fm.height()), as);
        p.drawText(QPointF(r.left() - fm.horizontalAdvance(fs) - 4, yOf(f) + fm.ascent() / 2.0),
                   fs);
    }
    p.drawText(QRectF(r.left(), r.bottom() + fm.height() + 2, r.width(), fm.height() + 4),
               Qt::AlignCenter, tr("Peak floor acceleration A (g)"));
    p.save();
    p.translate(14, r.center().y());
    p.rotate(-90);
    p.drawText(QRectF(-r.height() / 2, -fm.height() / 2.0 - 2, r.height(), fm.height() + 4),
               Qt::AlignCenter, tr("Frequency f (Hz)"));
    p.restore();
    // Colour bar.
    const QRectF bar(r.right() + 14, r.top(), 14, r.height());
    for (int y = 0; y < static_cast<int>(bar.height()); ++y)
        p.fillRect(QRectF(bar.left(), bar.bottom() - y - 1, bar.width(), 1),
                   gammaColor(y / bar.height()));
    p.drawRect(bar);
    p.drawText(QPointF(bar.right() + 3, bar.top() + fm.ascent()), QString::number(m_gMax, 'f', 2));
    p.drawText(QPointF(bar.right() + 3, bar.bottom()), QStringLiteral("0"));
    p.drawText(QPointF(bar.left(), bar.bottom() + fm.height() + 2), m_grid.gammaTitle);
}

void HeatMapView::mousePressEvent(QMouseEvent* e) {
    if (m_grid.empty() || !plotRect().contains(e->position())) return;
    auto nearest = [](const std::vector<double>& v, auto coord, double pos) {
        std::size_t best = 0;
        for (std::size_t i = 1; i < v.size(); ++i)
            if (std::abs(coord(v[i]) - pos) < std::abs(coord(v[best]) - pos)) best = i;
        return static_cast<int>(best);
    };
    const int ai = nearest(
        m_grid.amplitudes, [this](double a) { return xOf(a); }, e->position().x());
    const int fi = nearest(
        m_grid.frequencies, [this](double f) { return yOf(f); }, e->position().y());
    setSelected(ai, fi);
    emit pointSelected(ai, fi);
}

} // namespace kinstab::ui
