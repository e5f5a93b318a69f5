// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/RiskCharts.h"

#include "ui/NiceAxisTicks.h"

#include <QAreaSeries>
#include <QChart>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QLogValueAxis>
#include <QPen>
#include <QScatterSeries>
#include <QValueAxis>

#include <cmath>

namespace kinstab::ui {

namespace {

const QColor kHazardColour(40, 90, 160); // as the report's hazard figure (report/RiskSection)
const QColor kSetColour(214, 39, 40);
const QColor kTargetColour(120, 120, 120);

QString measureText(const HazardCurve& c) {
    return QString::fromStdString(hazardMeasureName(c.measure));
}

void reset(QChart* chart, const QString& title) {
    chart->removeAllSeries();
    for (QAbstractAxis* a : chart->axes())
        chart->removeAxis(a);
    chart->setTitle(title);
    chart->legend()->setAlignment(Qt::AlignBottom);
}

// Decades labelled 0.01, 0.1, 1, 10 with the 2..9 minor grid between them.
QLogValueAxis* logAxis(double lo, double hi, const QString& title) {
    auto* a = new QLogValueAxis;
    a->setBase(10.0);
    a->setLabelFormat("%g");
    a->setMinorTickCount(8);
    a->setRange(lo, hi);
    a->setTitleText(title);
    return a;
}

QLogValueAxis* intensityAxis(const HazardCurve& c) {
    const RiskAxisRange r = riskAxisRange(c);
    return logAxis(r.lo, r.hi, QObject::tr("intensity %1, g").arg(measureText(c)));
}

void attach(QChart* chart, QAbstractSeries* s, QAbstractAxis* x, QAbstractAxis* y) {
    chart->addSeries(s);
    s->attachAxis(x);
    s->attachAxis(y);
}

double decadeBelow(double v) {
    return std::pow(10.0, std::floor(std::log10(v)));
}

double decadeAbove(double v) {
    return std::pow(10.0, std::ceil(std::log10(v)));
}

} // namespace

RiskAxisRange riskAxisRange(const HazardCurve& c) {
    return {decadeBelow(c.points.front().imG), decadeAbove(c.points.back().imG)};
}

void clearRiskChart(QChart* chart, const QString& title) {
    reset(chart, title);
}

void fillHazardChart(QChart* chart, const HazardCurve& c, double targetRate) {
    reset(chart, QObject::tr("Hazard curve"));
    const double lowest = std::min(c.points.back().annualRate, targetRate);
    auto* y = logAxis(decadeBelow(lowest), decadeAbove(c.points.front().annualRate),
                      QObject::tr("λ(x), 1/yr"));
    y->setLabelFormat("%.0e");
    y->setMinorTickCount(0); // a decade per tick: the rates span many
    QLogValueAxis* x = intensityAxis(c);
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    auto* curve = new QLineSeries;
    curve->setName(QObject::tr("λ(x), %1 points").arg(c.points.size()));
    for (const HazardPoint& p : c.points)
        curve->append(p.imG, p.annualRate);
    curve->setPen(QPen(kHazardColour, 2.0));
    curve->setPointsVisible(true);
    attach(chart, curve, x, y);
    auto* target = new QLineSeries;
    target->setName(QObject::tr("target %1 /yr").arg(targetRate, 0, 'e', 2));
    target->append(x->min(), targetRate);
    target->append(x->max(), targetRate);
    target->setPen(QPen(kTargetColour, 1.0, Qt::DashLine));
    attach(chart, target, x, y);
}

void fillRiskFragilityChart(QChart* chart, const HazardCurve& c, const SetRisk* set) {
    reset(chart, QObject::tr("Fragility of the set"));
    auto* y = new QValueAxis;
    y->setRange(0.0, 1.0);
    y->setTitleText(QObject::tr("P(C | x)"));
    QLogValueAxis* x = intensityAxis(c);
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    useNiceTicks(y, 5);
    if (!set || !set->risk) return;
    auto* fit = new QLineSeries;
    fit->setName(QObject::tr("fit θ = %1 g, β = %2")
                     .arg(set->risk->fragility.medianG, 0, 'g', 3)
                     .arg(set->risk->fragility.beta, 0, 'g', 2));
    for (const RiskIntegrandPoint& p : set->integrand)
        fit->append(p.imG, p.pCollapse);
    fit->setPen(QPen(kSetColour, 2.0));
    attach(chart, fit, x, y);
    auto* points = new QScatterSeries;
    points->setName(QObject::tr("records"));
    points->setMarkerSize(7);
    points->setColor(kSetColour);
    for (const FragilityPoint& p : set->fragility.points)
        if (p.intensity >= x->min() && p.intensity <= x->max())
            points->append(p.intensity, p.probability);
    attach(chart, points, x, y);
}

void fillIntegrandChart(QChart* chart, const HazardCurve& c, const SetRisk* set) {
    reset(chart, QObject::tr("Where λ_C comes from"));
    auto* y = new QValueAxis;
    y->setTitleText(QObject::tr("dλ_C/d ln x, 1/yr"));
    QLogValueAxis* x = intensityAxis(c);
    chart->addAxis(x, Qt::AlignBottom);
    chart->addAxis(y, Qt::AlignLeft);
    if (!set || !set->risk) {
        y->setRange(0.0, 1.0);
        useNiceTicks(y, 5);
        return;
    }
    double top = 0.0;
    for (const RiskIntegrandPoint& p : set->integrand)
        top = std::max(top, p.density);
    // Rates are 1e-3 to 1e-7 per year: the axis counts in the power of ten of the peak, so its
    // ticks read 1, 2, 3 rather than 0.00001, 0.00002.
    const int exponent = top > 0.0 ? static_cast<int>(std::floor(std::log10(top))) : 0;
    const double unit = std::pow(10.0, exponent);
    y->setTitleText(QObject::tr("dλ_C/d ln x, 1e%1/yr").arg(exponent));
    auto* upper = new QLineSeries;
    auto* lower = new QLineSeries;
    for (const RiskIntegrandPoint& p : set->integrand) {
        upper->append(p.imG, p.density / unit);
        lower->append(p.imG, 0.0);
    }
    top /= unit;
    auto* area = new QAreaSeries(upper, lower);
    area->setName(
        QObject::tr("within the curve: %1 /yr").arg(set->risk->integral.withinCurve, 0, 'e', 2));
    QColor fill = kSetColour;
    fill.setAlpha(70);
    area->setBrush(fill);
    area->setPen(QPen(kSetColour, 1.5));
    attach(chart, area, x, y);
    // The rate beyond the last point is a mass at x_max, not a density: a dashed line marks
    // x_max and the legend gives the rate.
    auto* beyond = new QLineSeries;
    beyond->setName(QObject::tr("beyond %1 g: %2 /yr")
                        .arg(c.points.back().imG, 0, 'g', 3)
                        .arg(set->risk->integral.beyondLastPoint, 0, 'e', 2));
    beyond->append(c.points.back().imG, 0.0);
    beyond->append(c.points.back().imG, top);
    beyond->setPen(QPen(kTargetColour, 2.0, Qt::DashLine));
    attach(chart, beyond, x, y);
    y->setRange(0.0, top > 0.0 ? 1.1 * top : 1.0);
    useNiceTicks(y, 5);
}

} // namespace kinstab::ui
