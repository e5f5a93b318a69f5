// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/teaching/TracePainter.h"
#include "ui/NiceTicks.h"

#include "ui/teaching/TextScale.h"

#include "ui/teaching/StateStyle.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace kinstab::ui {

namespace {

const QColor kFuture(0xc8, 0xc8, 0xc8);
const QColor kAccel(0x1f, 0x3b, 0x73);
const QColor kAxis(0x44, 0x44, 0x44);

struct Axis {
    QRectF r;
    double t1, yLo, yHi;
    double lh; // one line of label text, from the label font (larger in presentation mode)
    double x(double t) const { return r.left() + r.width() * t / t1; }
    double y(double v) const { return r.bottom() - r.height() * (v - yLo) / (yHi - yLo); }
    QPointF at(double t, double v) const { return {x(t), y(v)}; }
};

// Room for a tick label such as "-0.75" beside the axis.
double tickLabelWidth(double lh) {
    return 3.0 * lh;
}

// A line of text inside the plot, just above the level v (right-aligned) or at its top (left).
QRectF insideAbove(const Axis& a, double v) {
    return {a.r.left() + 6, a.y(v) - a.lh - 1, a.r.width() - 12, a.lh};
}
QRectF insideTop(const Axis& a) {
    return {a.r.left() + 6, a.r.top() + 2, a.r.width() - 12, a.lh};
}

void paintFrame(QPainter& p, const Axis& a, const QString& label, double yStep, bool timeLabels) {
    p.setPen(QPen(QColor(0xe4, 0xe4, 0xe4), 1));
    const double tStep = niceTickStep(a.t1, 10);
    for (double t = 0; t <= a.t1 * (1 + 1e-9); t += tStep)
        p.drawLine(a.at(t, a.yLo), a.at(t, a.yHi));
    for (double v = std::ceil(a.yLo / yStep) * yStep; v <= a.yHi + 1e-12; v += yStep) {
        p.setPen(QPen(QColor(0xe4, 0xe4, 0xe4), 1));
        p.drawLine(a.at(0, v), a.at(a.t1, v));
        p.setPen(kAxis);
        const double w = tickLabelWidth(a.lh);
        p.drawText(QRectF(a.r.left() - w - 4, a.y(v) - a.lh / 2, w, a.lh),
                   Qt::AlignRight | Qt::AlignVCenter,
                   QString::number(std::abs(v) < 1e-12 ? 0.0 : v, 'g', 3));
    }
    p.setPen(QPen(kAxis, 1));
    p.drawRect(a.r);
    p.drawLine(a.at(0, 0), a.at(a.t1, 0));
    if (timeLabels)
        for (double t = 0; t <= a.t1 * (1 + 1e-9); t += tStep)
            p.drawText(QRectF(a.x(t) - 2 * a.lh, a.r.bottom() + 2, 4 * a.lh, a.lh), Qt::AlignCenter,
                       QString::number(t, 'g', 4));
    p.save();
    p.translate(a.r.left() - tickLabelWidth(a.lh) - 6, a.r.center().y());
    p.rotate(-90);
    p.drawText(QRectF(-a.r.height() / 2, -a.lh, a.r.height(), a.lh), Qt::AlignCenter, label);
    p.restore();
}

// A polyline split at the cursor: full colour before, grey after.
void paintSeries(QPainter& p, const Axis& a, const std::vector<TraceSample>& s, double cursor,
                 auto value, auto colourOf) {
    if (s.empty()) return;
    QPainterPath future;
    future.moveTo(a.at(s.front().tau, value(s.front())));
    for (const auto& x : s)
        future.lineTo(a.at(x.tau, value(x)));
    p.setPen(QPen(kFuture, 1.2));
    p.drawPath(future);
    // Past, one path per run of equal colour.
    for (std::size_t i = 1; i < s.size() && s[i - 1].tau < cursor;) {
        const QColor c = colourOf(s[i]);
        QPainterPath path;
        path.moveTo(a.at(s[i - 1].tau, value(s[i - 1])));
        for (; i < s.size() && s[i - 1].tau < cursor && colourOf(s[i]) == c; ++i) {
            if (s[i].tau <= cursor)
                path.lineTo(a.at(s[i].tau, value(s[i])));
            else {
                const double w = (cursor - s[i - 1].tau) / (s[i].tau - s[i - 1].tau);
                path.lineTo(a.at(cursor, value(s[i - 1]) + w * (value(s[i]) - value(s[i - 1]))));
            }
        }
        p.setPen(QPen(c, 1.8));
        p.drawPath(path);
    }
}

void paintAccel(QPainter& p, const Axis& a, const TeachingRun& run, double cursor) {
    const double mu = run.params().mu;
    const QRectF band(a.at(0, mu), a.at(a.t1, -mu));
    p.fillRect(band.normalized(), QColor(0x4a, 0x6f, 0xa5, 40));
    p.setPen(QPen(QColor(0x4a, 0x6f, 0xa5), 1, Qt::DashLine));
    p.drawLine(a.at(0, mu), a.at(a.t1, mu));
    p.drawLine(a.at(0, -mu), a.at(a.t1, -mu));
    p.drawText(insideAbove(a, mu), Qt::AlignRight | Qt::AlignVCenter,
               QStringLiteral("±μ = ±%1: sticks inside").arg(mu, 0, 'f', 2));
    const auto& s = run.trace();
    QPainterPath env, envLow;
    for (std::size_t i = 0; i < s.size(); ++i) {
        i == 0 ? env.moveTo(a.at(s[i].tau, s[i].envelope))
               : env.lineTo(a.at(s[i].tau, s[i].envelope));
        i == 0 ? envLow.moveTo(a.at(s[i].tau, -s[i].envelope))
               : envLow.lineTo(a.at(s[i].tau, -s[i].envelope));
    }
    p.setPen(QPen(QColor(0x99, 0x66, 0x00), 1, Qt::DashLine));
    p.drawPath(env);
    p.drawPath(envLow);
    if (run.planar()) { // the slip criterion is |a_h| > mu (gravity only: n = 1)
        QPainterPath h;
        for (std::size_t i = 0; i < s.size(); ++i)
            i == 0 ? h.moveTo(a.at(s[i].tau, s[i].accelH)) : h.lineTo(a.at(s[i].tau, s[i].accelH));
        p.setPen(QPen(QColor(0x2e, 0x8b, 0x57), 1, Qt::DotLine));
        p.drawPath(h);
        p.drawText(insideTop(a), Qt::AlignLeft | Qt::AlignVCenter,
                   QStringLiteral("a_x solid; |a_h| dotted: slips when above μ"));
    }
    paintSeries(
        p, a, s, cursor, [](const TraceSample& x) { return x.accel; },
        [](const TraceSample&) { return kAccel; });
}

void paintDelta(QPainter& p, const Axis& a, const TeachingRun& run, double cursor) {
    const double L = run.params().limit;
    p.setPen(QPen(stateColor(DisplayState::Collapse), 1.2, Qt::DashLine));
    p.drawLine(a.at(0, L), a.at(a.t1, L));
    p.drawLine(a.at(0, -L), a.at(a.t1, -L));
    p.drawText(insideAbove(a, L), Qt::AlignRight | Qt::AlignVCenter,
               QStringLiteral("bearing limit |δ| = %1: falls beyond").arg(L, 0, 'g', 3));
    if (run.planar()) { // along the walls, scaled so that its limit theta is at the same line
        const double k = L / run.params().theta;
        p.setPen(QPen(QColor(0x8e, 0x44, 0xad), 1.2, Qt::DashLine));
        QPainterPath y;
        const auto& s = run.trace();
        for (std::size_t i = 0; i < s.size(); ++i)
            i == 0 ? y.moveTo(a.at(s[i].tau, k * s[i].deltaY))
                   : y.lineTo(a.at(s[i].tau, k * s[i].deltaY));
        p.drawPath(y);
        p.drawText(insideTop(a), Qt::AlignLeft | Qt::AlignVCenter,
                   QStringLiteral("δx solid; δy·%1/Θ dashed (Θ = %2)")
                       .arg(L, 0, 'g', 3)
                       .arg(run.params().theta, 0, 'g', 3));
    }
    paintSeries(
        p, a, run.trace(), cursor, [](const TraceSample& x) { return x.delta; },
        [](const TraceSample& x) { return stateColor(x.state); });
}

void paintEventTicks(QPainter& p, const Axis& a, const TeachingRun& run) {
    const auto& ev = run.events();
    if (ev.size() > 600) return; // chattering: ticks would be a solid bar
    for (const SlabEvent& e : ev) {
        p.setPen(QPen(stateColor(displayStateOf(e.kind)), 2));
        p.drawLine(QPointF(a.x(e.tau), a.r.bottom()), QPointF(a.x(e.tau), a.r.bottom() - 7));
    }
}

double lineHeight(double labelPixels) {
    return std::ceil(labelPixels * 1.45);
}

} // namespace

double TraceLayout::tauAt(double x) const {
    return std::clamp((x - accelPlot.left()) / accelPlot.width() * tauEnd, 0.0, tauEnd);
}

TraceLayout traceLayout(const QRectF& area, const TeachingRun& run, double labelPixels) {
    // Margins follow the label font, so that presentation mode's larger text keeps its room.
    const double lh = lineHeight(labelPixels);
    const double left = area.left() + tickLabelWidth(lh) + lh + 10, right = area.right() - 12;
    const double top = area.top() + 8, bottom = area.bottom() - 2 * lh - 4;
    const double gap = lh + 6, h = (bottom - top - gap);
    TraceLayout l;
    l.accelPlot = QRectF(left, top, right - left, h * 0.5);
    l.deltaPlot = QRectF(left, top + h * 0.5 + gap, right - left, h * 0.5);
    l.tauEnd = run.displayEnd();
    l.lineHeight = lh;
    return l;
}

int traceLabelPixels(const QFont& viewFont) {
    return scaledPixels(viewFont, 11, kLabelMaxScale);
}

void paintTraces(QPainter& p, const QRectF& area, const TeachingRun& run, double cursorTau) {
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    p.fillRect(area, Qt::white);
    QFont font = p.font();
    font.setPixelSize(traceLabelPixels(p.font())); // larger in presentation mode
    p.setFont(font);
    const TraceLayout l = traceLayout(area, run, font.pixelSize());
    const double peak =
        run.params().amplitude * (run.planar() ? std::hypot(1.0, run.params().ayRatio) : 1.0);
    const double aMax = std::max(peak, run.params().mu) * 1.15;
    double dMax = run.params().limit * 1.25;
    for (const auto& s : run.trace())
        dMax = std::max(dMax, std::abs(s.delta) * 1.1);
    const Axis acc{l.accelPlot, l.tauEnd, -aMax, aMax, l.lineHeight};
    const Axis del{l.deltaPlot, l.tauEnd, -dMax, dMax, l.lineHeight};
    paintFrame(p, acc, QStringLiteral("a(τ)  [g]"), niceTickStep(2 * aMax, 4), false);
    paintFrame(p, del, QStringLiteral("δ(τ)  [d/2]"), niceTickStep(2 * dMax, 4), true);
    p.setClipRect(l.accelPlot.united(l.deltaPlot).adjusted(-1, -1, 1, 1));
    paintAccel(p, acc, run, cursorTau);
    paintDelta(p, del, run, cursorTau);
    paintEventTicks(p, del, run);
    p.setClipping(false);
    p.setPen(QPen(QColor(0xd0, 0x10, 0x10), 1.5));
    const double cx = acc.x(std::clamp(cursorTau, 0.0, l.tauEnd));
    p.drawLine(QPointF(cx, l.accelPlot.top()), QPointF(cx, l.deltaPlot.bottom()));
    p.setPen(kAxis);
    p.drawText(QRectF(l.deltaPlot.left(), l.deltaPlot.bottom() + l.lineHeight + 2,
                      l.deltaPlot.width(), l.lineHeight),
               Qt::AlignCenter,
               QStringLiteral("τ = t / t*   (t* = %1 s)").arg(run.tstar(), 0, 'f', 4));
    p.restore();
}

} // namespace kinstab::ui
