// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/FloorCharts.h"

#include "core/excitation/RecordedMotion.h"
#include "core/slab/History.h"
#include "core/slab/RecordRun.h"
#include "core/slab/SlabRecorder.h"
#include "ui/DockedChart.h"
#include "ui/NiceAxisTicks.h"

#include <QLineSeries>
#include <QScatterSeries>
#include <QValueAxis>

#include <algorithm>
#include <cmath>

namespace kinstab::ui {

namespace {

QValueAxis* axis(QChart* chart, const QString& title, Qt::Alignment side, double lo, double hi) {
    auto* a = new QValueAxis;
    a->setTitleText(title);
    a->setRange(lo, hi);
    useNiceTicks(a);
    chart->addAxis(a, side);
    return a;
}

void attach(QChart* chart, QAbstractSeries* s, QAbstractAxis* x, QAbstractAxis* y) {
    chart->addSeries(s);
    s->attachAxis(x);
    s->attachAxis(y);
}

QLineSeries* profile(const QString& name, const QColor& c, Qt::PenStyle style,
                     const std::vector<double>& values, const std::vector<double>& heights) {
    QLineSeries* s = chartLine(name, c, 2.0, style);
    for (std::size_t i = 0; i < values.size(); ++i)
        s->append(values[i], heights[i]);
    return s;
}

QString heightTitle(const QString& unit) {
    return QObject::tr("height, %1").arg(unit); // above the base; longer was elided
}

} // namespace

void clearChart(QChart* chart) {
    chart->removeAllSeries();
    for (QAbstractAxis* a : chart->axes())
        chart->removeAxis(a);
}

void fillProfileChart(QChart* chart, const FloorAnalysis& a, const std::vector<double>& heights,
                      const QString& unit) {
    clearChart(chart);
    chart->setTitle(QObject::tr("Peak floor acceleration (model: record as given)"));
    double hi = std::max(a.sdofRoofPeak, *std::max_element(a.pfa.begin(), a.pfa.end()));
    for (const FloorDemand& d : a.demands)
        hi = std::max(hi, *std::max_element(d.pfa.begin(), d.pfa.end()));
    QValueAxis* x = axis(chart, QObject::tr("PFA, g"), Qt::AlignBottom, 0.0, 1.05 * hi);
    QValueAxis* y = axis(chart, heightTitle(unit), Qt::AlignLeft, 0.0, 1.05 * heights.back());
    QLineSeries* model =
        profile(QObject::tr("model"), QColor(0, 90, 181), Qt::SolidLine, a.pfa, heights);
    model->insert(0, QPointF(a.pga, 0.0)); // the ground's own peak at the base
    model->setPointsVisible(true);
    attach(chart, model, x, y);
    for (const FloorDemand& d : a.demands) {
        const QColor colour = d.code == "ec8" ? QColor(30, 140, 60) : QColor(200, 60, 30);
        const QString name = d.code == "asce7_22"       ? QObject::tr("ASCE design")
                             : d.code == "asce7_22_mce" ? QObject::tr("ASCE MCE_R")
                                                        : QObject::tr("EC8 rigid");
        // EN 1998-1 with an element period T_a > 0 is no longer the rigid element's demand.
        const bool ec8WithPeriod =
            d.code == "ec8" && std::any_of(d.trail.begin(), d.trail.end(), [](const TrailEntry& t) {
                return t.symbol == "T_a" && t.value > 0.0;
            });
        attach(chart,
               profile(ec8WithPeriod ? QObject::tr("EC8") : name, colour,
                       d.code == "asce7_22_mce" ? Qt::DashLine : Qt::SolidLine, d.pfa, heights),
               x, y);
    }
    auto* sdof = new QScatterSeries;
    sdof->setName(QObject::tr("SDOF (paper)"));
    sdof->setMarkerSize(11);
    sdof->setColor(QColor(120, 120, 120));
    sdof->append(a.sdofRoofPeak, heights.back());
    attach(chart, sdof, x, y);
}

void fillCriticalChart(QChart* chart, const FloorAnalysis& a, const std::vector<double>& heights,
                       const QString& unit) {
    clearChart(chart);
    chart->setTitle(QObject::tr("Critical PGA: the slab on the level falls"));
    double hi = a.pga;
    QLineSeries* crit =
        chartLine(QObject::tr("critical PGA of the record"), QColor(160, 0, 120), 2.0);
    crit->setPointsVisible(true);
    for (const LevelCritical& l : a.critical)
        if (l.criticalPga) {
            crit->append(*l.criticalPga, heights[static_cast<std::size_t>(l.level - 1)]);
            hi = std::max(hi, *l.criticalPga);
        }
    QValueAxis* x = axis(chart, QObject::tr("PGA, g"), Qt::AlignBottom, 0.0, 1.1 * hi);
    QValueAxis* y = axis(chart, heightTitle(unit), Qt::AlignLeft, 0.0, 1.05 * heights.back());
    attach(chart, crit, x, y);
    QLineSeries* pga =
        chartLine(QObject::tr("record's PGA"), QColor(0, 90, 181), 1.5, Qt::DashLine);
    pga->append(a.pga, 0.0);
    pga->append(a.pga, heights.back());
    attach(chart, pga, x, y);
}

QString fillLevelChart(QChart* chart, const FloorAnalysis& a, const Accelerogram& ground,
                       const Slab1DCase& slab, int level) {
    clearChart(chart);
    const Accelerogram& m = a.motions[static_cast<std::size_t>(level - 1)];
    chart->setTitle(
        QObject::tr("Level %1: floor motion and the slab's run (record as given)").arg(level));
    const double peak = std::abs(m.peak().value);
    const RecordedMotion motion(m, slab.tstar, peak);
    SlabHistoryLog log(motion, slab.slab.mu);
    const SlabResult run = runRecord1D(slab, m, peak, {}, &log);
    const History h = log.history(run.tauEnd, 0.05);
    const double tEnd = m.dt * static_cast<double>(m.size() - 1);
    QValueAxis* x = axis(chart, QObject::tr("time, s"), Qt::AlignBottom, 0.0, tEnd);
    const double amax = std::max(peak, std::abs(ground.peak().value));
    QValueAxis* y = axis(chart, QObject::tr("acceleration, g"), Qt::AlignLeft, -amax, amax);
    QValueAxis* d = axis(chart, QObject::tr("slab δ/(d/2)"), Qt::AlignRight, -1.1, 1.1);
    QLineSeries* g = chartLine(QObject::tr("ground"), QColor(150, 150, 150), 1.0);
    for (std::size_t k = 0; k < ground.size(); ++k)
        g->append(ground.dt * static_cast<double>(k), ground.samples[k]);
    QLineSeries* f = chartLine(QObject::tr("level %1").arg(level), QColor(0, 90, 181), 1.0);
    for (std::size_t k = 0; k < m.size(); ++k)
        f->append(m.dt * static_cast<double>(k), m.samples[k]);
    QLineSeries* s = chartLine(QObject::tr("slab δ/(d/2)"), QColor(200, 60, 30), 2.0);
    for (const HistorySample& p : h.samples)
        s->append(p.tau * slab.tstar, p.delta);
    attach(chart, g, x, y);
    attach(chart, f, x, y);
    attach(chart, s, x, d);
    if (run.outcome == Outcome::Collapsed)
        return QObject::tr("the slab falls at %1 s").arg(run.tauC * slab.tstar, 0, 'f', 2);
    return QObject::tr("the slab stays (%1), max |δ|/(d/2) = %2")
        .arg(QString::fromStdString(outcomeName(run.outcome)))
        .arg(run.maxAbsDelta, 0, 'f', 3);
}

} // namespace kinstab::ui
