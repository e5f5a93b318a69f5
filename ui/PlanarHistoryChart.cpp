// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/PlanarHistoryChart.h"

#include "ui/DockedChart.h"
#include "ui/NiceAxisTicks.h"

#include <QLineSeries>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace kinstab::ui {

namespace {
QString outcomeText(const PlanarPointRun& run) {
    const PlanarResult& r = run.result;
    if (r.slab.outcome != Outcome::Collapsed)
        return QString::fromStdString(outcomeName(r.slab.outcome));
    return QObject::tr("falls %1, τc = %2, γc = %3")
        .arg(QString::fromStdString(exitSideName(r.exitSide)))
        .arg(r.slab.tauC, 0, 'f', 2)
        .arg(run.tauRef / r.slab.tauC, 0, 'f', 3);
}
} // namespace

PlanarHistoryChart::PlanarHistoryChart(QWidget* parent)
    : QChartView(parent), m_dx(chartLine(tr("δx / (d/2), across"), QColor(20, 20, 20), 2)),
      m_dy(chartLine(tr("δy / (d/2), along"), QColor(40, 120, 200), 1.5)),
      m_limitUp(chartLine(tr("±limit (across)"), QColor(200, 40, 40), 1, Qt::DashLine)),
      m_limitDown(chartLine(QString(), QColor(200, 40, 40), 1, Qt::DashLine)), m_x(new QValueAxis),
      m_yx(new QValueAxis), m_yy(new QValueAxis) {
    auto* c = new QChart;
    c->setAnimationOptions(QChart::NoAnimation);
    c->setMargins(QMargins(4, 4, 4, 4));
    for (QLineSeries* s : {m_limitUp, m_limitDown, m_dy, m_dx})
        c->addSeries(s);
    m_x->setTitleText(tr("τ = t / t*"));
    m_yx->setTitleText(tr("δx"));
    m_yy->setTitleText(tr("δy"));
    m_yy->setLabelsColor(QColor(40, 120, 200));
    c->addAxis(m_x, Qt::AlignBottom);
    c->addAxis(m_yx, Qt::AlignLeft);
    c->addAxis(m_yy, Qt::AlignRight);
    for (QLineSeries* s : {m_dx, m_limitUp, m_limitDown}) {
        s->attachAxis(m_x);
        s->attachAxis(m_yx);
    }
    m_dy->attachAxis(m_x);
    m_dy->attachAxis(m_yy);
    useNiceTicks(c); // 1-2-5 ticks whatever range an update sets
    installDockedChart(this, c,
                       tr("Planar history of one point (after Run: pick a point on the surface)"));
    hideFromLegend(c, {m_limitDown});
}

int PlanarHistoryChart::sampleCount() const {
    return static_cast<int>(m_dx->count());
}

void PlanarHistoryChart::setRun(const PlanarPointRun& run) {
    QList<QPointF> dx, dy;
    // The path starts at the first slip: the slab sits still on its walls before it.
    if (!run.path.empty() && run.path.front().tau > 0) {
        dx.append({0, 0});
        dy.append({0, 0});
    }
    double xMax = run.limit, yMax = 0.1;
    for (const PlanarSample& s : run.path) {
        dx.append({s.tau, s.dx});
        dy.append({s.tau, s.dy});
        xMax = std::max(xMax, std::abs(s.dx));
        yMax = std::max(yMax, std::abs(s.dy));
    }
    const double tauEnd = run.path.empty() ? 1.0 : run.path.back().tau;
    m_dx->replace(dx);
    m_dy->replace(dy);
    m_limitUp->replace({{0, run.limit}, {tauEnd, run.limit}});
    m_limitDown->replace({{0, -run.limit}, {tauEnd, -run.limit}});
    m_x->setRange(0, tauEnd);
    m_yx->setRange(-1.15 * xMax, 1.15 * xMax);
    m_yy->setRange(-1.15 * yMax, 1.15 * yMax);
    chart()->setTitle(tr("Planar, A = %1 g, f = %2 Hz: %3")
                          .arg(run.amplitude, 0, 'f', 3)
                          .arg(run.frequency, 0, 'f', 3)
                          .arg(outcomeText(run)));
}

void PlanarHistoryChart::clearRun() {
    for (QLineSeries* s : {m_dx, m_dy, m_limitUp, m_limitDown})
        s->clear();
    chart()->setTitle(tr("Planar history of one point (after Run: pick a point on the surface)"));
}

} // namespace kinstab::ui
