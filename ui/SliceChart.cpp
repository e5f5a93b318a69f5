// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/SliceChart.h"

#include "ui/DockedChart.h"
#include "ui/NiceAxisTicks.h"

#include <QLineSeries>
#include <QScatterSeries>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace kinstab::ui {

SliceChart::SliceChart(QWidget* parent)
    : QChartView(parent), m_gamma(new QLineSeries), m_tau(new QScatterSeries), m_x(new QValueAxis),
      m_yGamma(new QValueAxis), m_yTau(new QValueAxis) {
    auto* c = new QChart;
    c->setAnimationOptions(QChart::NoAnimation);
    c->setMargins(QMargins(4, 4, 4, 4));
    m_gamma->setName(tr("γc"));
    m_gamma->setPointsVisible(true);
    m_gamma->setPen(QPen(QColor(200, 60, 40), 2));
    m_tau->setName(tr("τc (collapse time)"));
    m_tau->setMarkerSize(6);
    m_tau->setColor(QColor(40, 90, 170));
    c->addSeries(m_gamma);
    c->addSeries(m_tau);
    m_x->setTitleText(tr("A (g)"));
    m_yGamma->setTitleText(tr("γc"));
    m_yTau->setTitleText(tr("τc"));
    c->addAxis(m_x, Qt::AlignBottom);
    c->addAxis(m_yGamma, Qt::AlignLeft);
    c->addAxis(m_yTau, Qt::AlignRight);
    m_gamma->attachAxis(m_x);
    m_gamma->attachAxis(m_yGamma);
    m_tau->attachAxis(m_x);
    m_tau->attachAxis(m_yTau);
    useNiceTicks(c); // 1-2-5 ticks whatever range an update sets
    installDockedChart(this, c, tr("γc and τc against A (after Run: pick a point on the surface)"));
}

void SliceChart::setSlice(double f, const std::vector<double>& amplitudes,
                          const std::vector<double>& gamma, const std::vector<double>& tauC,
                          const QString& gammaTitle) {
    QList<QPointF> g, t;
    double gMax = 0, tMax = 0;
    for (std::size_t i = 0; i < amplitudes.size(); ++i) {
        if (std::isfinite(gamma[i])) {
            g.append({amplitudes[i], gamma[i]});
            gMax = std::max(gMax, gamma[i]);
        }
        if (std::isfinite(tauC[i])) {
            t.append({amplitudes[i], tauC[i]});
            tMax = std::max(tMax, tauC[i]);
        }
    }
    m_gamma->replace(g);
    m_tau->replace(t);
    m_gamma->setName(gammaTitle);
    if (!amplitudes.empty())
        m_x->setRange(amplitudes.front(), std::max(amplitudes.back(), amplitudes.front() + 1e-6));
    m_yGamma->setRange(0, gMax > 0 ? 1.1 * gMax : 1.0);
    m_yTau->setRange(0, tMax > 0 ? 1.1 * tMax : 1.0);
    chart()->setTitle(tr("γc and τc against A at f = %1 Hz (cf. Fig. 34)").arg(f, 0, 'f', 3));
}

void SliceChart::clearSlice() {
    m_gamma->clear();
    m_tau->clear();
    chart()->setTitle(tr("γc and τc against A (after Run: pick a point on the surface)"));
}

} // namespace kinstab::ui
