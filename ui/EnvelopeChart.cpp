// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/EnvelopeChart.h"

#include "ui/NiceAxisTicks.h"
#include <QLineSeries>
#include <QScatterSeries>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace kinstab::ui {

EnvelopeChart::EnvelopeChart(QWidget* parent)
    : QChartView(parent), m_curve(new QLineSeries), m_marks(new QScatterSeries),
      m_x(new QValueAxis), m_y(new QValueAxis) {
    auto* c = new QChart;
    c->setAnimationOptions(QChart::NoAnimation);
    c->legend()->hide();
    c->setMargins(QMargins(2, 2, 2, 2));
    c->addSeries(m_curve);
    c->addSeries(m_marks);
    m_marks->setMarkerSize(7);
    m_x->setTitleText(tr("t (s)"));
    m_y->setTitleText(tr("e / e_max"));
    m_y->setRange(0, 1.05);
    c->addAxis(m_x, Qt::AlignBottom);
    c->addAxis(m_y, Qt::AlignLeft);
    for (auto* s :
         {static_cast<QAbstractSeries*>(m_curve), static_cast<QAbstractSeries*>(m_marks)}) {
        s->attachAxis(m_x);
        s->attachAxis(m_y);
    }
    useNiceTicks(m_x);
    useNiceTicks(m_y, 2); // 0, 0.5, 1 in a short chart
    setChart(c);
    setRenderHint(QPainter::Antialiasing);
    setMinimumHeight(150);
    setToolTip(tr("Envelope e(t) = exp(−αt) − exp(−βt) of the floor acceleration, normalized to "
                  "its peak. Dots: rise (half maximum), peak, and end of strong motion (half "
                  "maximum on the way down)."));
}

void EnvelopeChart::setEnvelope(const Envelope& e, double tstar) {
    const CharacteristicTimes times = e.computedTimes(tstar);
    const double tMax = times.tauMax * tstar;
    const double tEnd =
        std::isfinite(times.tauDur) ? std::min(1.3 * times.tauDur * tstar, 600.0) : 60.0;
    auto env = [&](double t) { return std::exp(-e.alpha * t) - std::exp(-e.beta * t); };
    const double peak = std::isfinite(tMax) ? env(tMax) : 1.0;
    QList<QPointF> pts;
    constexpr int n = 300;
    for (int k = 0; k <= n; ++k) {
        const double t = tEnd * k / n;
        pts.append({t, env(t) / peak});
    }
    m_curve->replace(pts);
    QList<QPointF> marks;
    for (double tau : {times.tauRise, times.tauMax, times.tauDur})
        if (std::isfinite(tau) && tau * tstar <= tEnd)
            marks.append({tau * tstar, env(tau * tstar) / peak});
    m_marks->replace(marks);
    m_x->setRange(0, tEnd);
}

} // namespace kinstab::ui
