// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/HistoryChart.h"

#include "ui/DockedChart.h"
#include "ui/NiceAxisTicks.h"

#include <QAreaSeries>
#include <QLineSeries>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace kinstab::ui {

HistoryChart::HistoryChart(QWidget* parent)
    : QChartView(parent), m_delta(chartLine(tr("δ / (d/2)"), QColor(20, 20, 20), 2)),
      m_accel(chartLine(tr("a (g)"), QColor(70, 130, 200), 1)),
      m_envUp(chartLine(tr("envelope"), QColor(230, 120, 30), 1.5)),
      m_envDown(chartLine(QString(), QColor(230, 120, 30), 1.5)),
      m_muUp(chartLine(tr("±μ"), QColor(120, 120, 120), 1, Qt::DashLine)),
      m_muDown(chartLine(QString(), QColor(120, 120, 120), 1, Qt::DashLine)),
      m_slipTop(new QLineSeries), m_slipBase(new QLineSeries),
      m_slip(new QAreaSeries(m_slipTop, m_slipBase)), m_x(new QValueAxis), m_yDelta(new QValueAxis),
      m_yAccel(new QValueAxis) {
    auto* c = new QChart;
    c->setAnimationOptions(QChart::NoAnimation);
    c->setMargins(QMargins(4, 4, 4, 4));
    m_slip->setName(tr("slipping"));
    m_slip->setColor(QColor(255, 200, 120, 110));
    m_slip->setBorderColor(Qt::transparent);
    c->addSeries(m_slip);
    for (QLineSeries* s : {m_accel, m_envUp, m_envDown, m_muUp, m_muDown, m_delta})
        c->addSeries(s);
    m_x->setTitleText(tr("τ = t / t*"));
    m_yDelta->setTitleText(tr("δ / (d/2)"));
    m_yAccel->setTitleText(tr("a (g)"));
    c->addAxis(m_x, Qt::AlignBottom);
    c->addAxis(m_yDelta, Qt::AlignLeft);
    c->addAxis(m_yAccel, Qt::AlignRight);
    m_slip->attachAxis(m_x);
    m_slip->attachAxis(m_yDelta);
    m_delta->attachAxis(m_x);
    m_delta->attachAxis(m_yDelta);
    for (QLineSeries* s : {m_accel, m_envUp, m_envDown, m_muUp, m_muDown}) {
        s->attachAxis(m_x);
        s->attachAxis(m_yAccel);
    }
    useNiceTicks(c); // 1-2-5 ticks whatever range an update sets
    installDockedChart(this, c,
                       tr("History of one point (after Run: pick a point on the surface)"));
    hideFromLegend(c, {m_envDown, m_muDown}); // the lower envelope and -μ have no name
}

int HistoryChart::sampleCount() const {
    return static_cast<int>(m_delta->count());
}

namespace {

// Slip shading: a step curve at the top of the δ axis (±yd) while slipping, at its bottom
// otherwise, and the base the area fills down to.
std::pair<QList<QPointF>, QList<QPointF>> slipShading(const std::vector<HistorySample>& samples,
                                                      double yd) {
    QList<QPointF> top, base;
    double previous = 0;
    for (const HistorySample& s : samples) {
        const double v = s.state != 0 ? yd : -yd;
        if (!top.isEmpty() && v != previous) top.append({s.tau, previous});
        top.append({s.tau, v});
        previous = v;
    }
    for (const QPointF& p : top)
        base.append({p.x(), -yd});
    return {top, base};
}

// "A = …, f = …: collapses at τc = … (γc = …), n slip intervals (cf. Fig. 35)".
QString historyTitle(const PointRun& run) {
    const SlabResult& r = run.result;
    const QString outcome = r.outcome == Outcome::Collapsed
                                ? HistoryChart::tr("collapses at τc = %1 (γc = %2)")
                                      .arg(r.tauC, 0, 'f', 2)
                                      .arg(run.tauRef / r.tauC, 0, 'f', 3)
                                : QString::fromStdString(outcomeName(r.outcome));
    const QString drive = run.drive.empty() ? HistoryChart::tr("A = %1 g, f = %2 Hz")
                                                  .arg(run.amplitude, 0, 'f', 3)
                                                  .arg(run.frequency, 0, 'f', 3)
                                            : QString::fromStdString(run.drive);
    return HistoryChart::tr("%1: %2, %3 slip intervals (cf. Fig. 35)")
        .arg(drive, outcome)
        .arg(r.slipIntervals);
}

} // namespace

void HistoryChart::setRun(const PointRun& run) {
    QList<QPointF> delta, accel;
    double dMax = run.limit;
    const double tauEnd = run.envelope.empty() ? 1.0 : run.envelope.back().tau;
    for (const HistorySample& s : run.history.samples) {
        delta.append({s.tau, s.delta});
        accel.append({s.tau, s.accel});
        dMax = std::max(dMax, std::abs(s.delta));
    }
    const double yd = 1.15 * dMax;
    const auto [top, base] = slipShading(run.history.samples, yd);
    QList<QPointF> up, down;
    double aMax = run.mu;
    for (const EnvelopeSample& e : run.envelope) {
        up.append({e.tau, e.bound});
        down.append({e.tau, -e.bound});
        aMax = std::max(aMax, e.bound);
    }
    m_delta->replace(delta);
    m_accel->replace(accel);
    m_envUp->replace(up);
    m_envDown->replace(down);
    m_muUp->replace({{0, run.mu}, {tauEnd, run.mu}});
    m_muDown->replace({{0, -run.mu}, {tauEnd, -run.mu}});
    m_slipTop->replace(top);
    m_slipBase->replace(base);
    m_x->setRange(0, tauEnd);
    m_yDelta->setRange(-yd, yd);
    m_yAccel->setRange(-1.15 * aMax, 1.15 * aMax);
    chart()->setTitle(historyTitle(run));
}

void HistoryChart::clearRun() {
    for (QLineSeries* s :
         {m_delta, m_accel, m_envUp, m_envDown, m_muUp, m_muDown, m_slipTop, m_slipBase})
        s->clear();
    chart()->setTitle(tr("History of one point (after Run: pick a point on the surface)"));
}

} // namespace kinstab::ui
