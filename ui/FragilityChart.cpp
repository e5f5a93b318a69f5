// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/FragilityChart.h"

#include "ui/NiceAxisTicks.h"
#include <QChart>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QPen>
#include <QScatterSeries>
#include <QValueAxis>

#include <algorithm>

namespace kinstab::ui {

namespace {

// A set's name in the legend: only what tells it from the other sets (μ and t* when they vary,
// the driving motion when it is not the ground record), so six sets still fit their legend.
QString setName(const StudyRow& p, const std::vector<Fragility>& sets) {
    QStringList parts;
    const StudyRow& first = sets.front().parameters;
    const auto varies = [&](auto field) {
        return std::any_of(sets.begin(), sets.end(),
                           [&](const Fragility& f) { return f.parameters.*field != first.*field; });
    };
    if (varies(&StudyRow::mu)) parts << QString("μ = %1").arg(p.mu);
    if (varies(&StudyRow::tstar)) parts << QString("t* = %1 s").arg(p.tstar);
    if (p.floorPeriod || p.level || p.motion) parts << QString::fromStdString(studyDriverText(p));
    if (parts.isEmpty()) parts << QString("μ = %1, t* = %2 s").arg(p.mu).arg(p.tstar);
    return parts.join(", ");
}

QLineSeries* line(const std::vector<FragilityCurvePoint>& curve, double FragilityCurvePoint::*p) {
    auto* s = new QLineSeries;
    for (const auto& c : curve)
        s->append(c.intensity, c.*p);
    return s;
}

// A bootstrap bound: its points where the bootstrap gave one.
QLineSeries* line(const std::vector<FragilityCurvePoint>& curve,
                  std::optional<double> FragilityCurvePoint::*p) {
    auto* s = new QLineSeries;
    for (const auto& c : curve)
        if (c.*p) s->append(c.intensity, *(c.*p));
    return s;
}

// A set's legend name with its fit (median, β and their flags) or why there is none.
QString fittedName(const Fragility& f, const std::vector<Fragility>& sets) {
    const QString name = setName(f.parameters, sets);
    if (!f.fit) return name + QObject::tr(" (no fit: %1)").arg(QString::fromStdString(f.noFit));
    return name + QString(": θ = %1 g%2, β = %3%4")
                      .arg(f.fit->median, 0, 'g', 3)
                      .arg(f.medianBeyondSearch ? QObject::tr(" (extrapolated)") : QString())
                      .arg(f.fit->beta, 0, 'g', 2)
                      .arg(f.betaAtBound ? QObject::tr(" (at bound)") : QString());
}

// A set's series: the fitted curve and its bootstrap bounds when there is a fit, then the
// observed points (always last).
QList<QXYSeries*> setSeries(const Fragility& f) {
    QList<QXYSeries*> series;
    if (f.fit) {
        series << line(f.curve, &FragilityCurvePoint::probability);
        if (f.medianLower)
            series << line(f.curve, &FragilityCurvePoint::lower)
                   << line(f.curve, &FragilityCurvePoint::upper);
    }
    auto* points = new QScatterSeries;
    points->setMarkerSize(8);
    for (const auto& p : f.points)
        points->append(p.intensity, p.probability);
    series << points;
    return series;
}

// Fresh axes: the critical intensity across, P(collapse) from 0 to 1 up.
std::pair<QValueAxis*, QValueAxis*> freshAxes(QChart* chart, const std::vector<Fragility>& sets) {
    chart->removeAllSeries();
    for (QAbstractAxis* a : chart->axes())
        chart->removeAxis(a);
    auto* x = new QValueAxis;
    auto* y = new QValueAxis;
    const QString measure =
        sets.empty() ? QString() : QString::fromStdString(sets.front().parameters.measure);
    x->setTitleText(QObject::tr("critical intensity %1, g").arg(measure.toUpper()));
    y->setTitleText(QObject::tr("P(collapse)"));
    y->setRange(0.0, 1.0);
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    useNiceTicks(x);
    useNiceTicks(y, 5);
    return {x, y};
}

// Adds one set's series in its colour: the first bold and named, bounds dashed. Returns the
// largest intensity among them (0 for none).
double addSet(QChart* chart, const QList<QXYSeries*>& series, const QColor& colour,
              const QString& name, QValueAxis* x, QValueAxis* y) {
    double top = 0.0;
    for (int k = 0; k < series.size(); ++k) {
        QXYSeries* s = series[k];
        const bool dashed = k > 0 && k + 1 < series.size(); // the last is the points
        s->setPen(QPen(colour, k == 0 ? 2.0 : 1.0, dashed ? Qt::DashLine : Qt::SolidLine));
        s->setColor(colour);
        s->setName(k == 0 ? name : QString());
        chart->addSeries(s);
        s->attachAxis(x);
        s->attachAxis(y);
        for (const QPointF& pt : s->points())
            top = std::max(top, pt.x());
    }
    return top;
}

// Ten distinct colours (the "tab10" palette) before any repeats.
const QList<QColor>& setColours() {
    static const QList<QColor> colours = {
        QColor(31, 119, 180), QColor(214, 39, 40), QColor(44, 160, 44),   QColor(148, 103, 189),
        QColor(255, 127, 14), QColor(140, 86, 75), QColor(227, 119, 194), QColor(127, 127, 127),
        QColor(188, 189, 34), QColor(23, 190, 207)};
    return colours;
}

} // namespace

void fillFragilityChart(QChart* chart, const std::vector<Fragility>& sets) {
    const auto [x, y] = freshAxes(chart, sets);
    const QList<QColor>& colours = setColours();
    double top = 0.0;
    for (std::size_t i = 0; i < sets.size(); ++i) {
        const QColor colour = colours[static_cast<int>(i) % colours.size()];
        top = std::max(top,
                       addSet(chart, setSeries(sets[i]), colour, fittedName(sets[i], sets), x, y));
    }
    // One legend entry per set: the named series (the fitted curve, or the points without a fit).
    for (QLegendMarker* m : chart->legend()->markers())
        m->setVisible(!m->label().isEmpty());
    x->setRange(0.0, top > 0.0 ? 1.05 * top : 1.0); // a margin: the last point is not on the edge
}

} // namespace kinstab::ui
