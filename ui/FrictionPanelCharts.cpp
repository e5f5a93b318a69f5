// SPDX-License-Identifier: GPL-3.0-or-later
// FrictionPanel, continued: its two charts - the composite test curves with the fitted decay law
// (Furgerson 1980, Figs. 18-20) and V∞ against confining pressure with the Coulomb line (Fig. 21).

#include "ui/FrictionChartParts.h"
#include "ui/FrictionPanel.h"

#include <QChart>
#include <QChartView>
#include <QComboBox>
#include <QLineSeries>
#include <QPen>
#include <QScatterSeries>

#include <algorithm>

namespace kinstab::ui {

using namespace friction;

void FrictionPanel::fillCurveChart() {
    // Figs. 18-20: the composite test curve (points) and the fitted decay law (line) per CP.
    const ShownUnits u = shownUnits(units_);
    QList<QAbstractSeries*> series;
    double vMax = 1.0, dMax = 0.0;
    int k = 0;
    for (const GroupCalibration& g : calibration_.groups) {
        if (QString::fromStdString(g.configuration) != configuration_->currentText()) continue;
        const TripletCurve& c = g.composite;
        const Eigen::VectorXd dense =
            Eigen::VectorXd::LinSpaced(121, c.delta(0), c.delta(c.delta.size() - 1));
        const Eigen::VectorXd fitted = evaluateDecay(g.fit, c, dense);
        QList<QPointF> line, points;
        for (Eigen::Index i = 0; i < dense.size(); ++i)
            line.append({u.length * dense(i), u.force * fitted(i)});
        for (Eigen::Index i = 0; i < c.delta.size(); ++i)
            points.append({u.length * c.delta(i), u.force * c.shear(i)});
        auto* l = new QLineSeries;
        l->replace(line);
        l->setName(tr("CP %1 %2").arg(g.cpPsi * u.pressure, 0, 'f', 0).arg(u.p));
        l->setPen(QPen(cpColor(k), 2));
        auto* s = new QScatterSeries;
        s->replace(points);
        s->setName(tr("CP %1 test").arg(g.cpPsi * u.pressure, 0, 'f', 0));
        s->setProperty("hideInLegend", true);
        s->setColor(cpColor(k));
        s->setMarkerSize(7);
        series << s << l;
        vMax = std::max(vMax, u.force * c.shear.maxCoeff());
        dMax = std::max(dMax, u.length * c.delta.maxCoeff());
        ++k;
    }
    curves_->chart()->setTitle(tr("%1: V(δ) after fracture, composite tests and fitted law")
                                   .arg(configuration_->currentText()));
    resetChart(curves_->chart(), series,
               axis(tr("δ (%1)").arg(u.l), 0.0, dMax > 0 ? dMax : 0.4 * u.length),
               axis(tr("V (%1)").arg(u.f), 0.0, 1.05 * vMax));
}

namespace {

// How Fig. 21 is drawn: CP in the shown pressure unit, V∞ times `scale` (the shown force, or
// the shown pressure over A_b), points up to maxCpPsi fitted, the fit with or without intercept.
struct CoulombScales {
    double cp = 1, scale = 1, maxCpPsi = 0;
    bool intercept = true;
};

// A configuration's Coulomb line from CP = 0 to the fit's limit.
QLineSeries* coulombLine(const ConfigurationCalibration& c, const CoulombScales& cs,
                         const QColor& colour) {
    const double slope =
        cs.intercept ? c.coulomb->slopeWithIntercept : c.coulomb->slopeThroughOrigin;
    const double v0 = cs.intercept ? c.coulomb->interceptKips : 0.0;
    const double top = cs.maxCpPsi;
    auto* l = new QLineSeries;
    l->replace({QPointF(0.0, cs.scale * v0), QPointF(cs.cp * top, cs.scale * (v0 + slope * top))});
    l->setName(FrictionPanel::tr("%1 fit").arg(QString::fromStdString(c.configuration)));
    l->setPen(QPen(colour, 2, Qt::DashLine));
    return l;
}

// One configuration's series: the fitted points, those above the limit (lighter squares) and
// its Coulomb line. yMax and cpMax grow to hold its points.
QList<QAbstractSeries*> configurationSeries(const ConfigurationCalibration& c,
                                            const CoulombScales& cs, const QColor& colour,
                                            double& yMax, double& cpMax) {
    QList<QPointF> used, excluded;
    for (const CoulombPoint& p : c.points) {
        (p.cpPsi <= cs.maxCpPsi ? used : excluded).append({cs.cp * p.cpPsi, cs.scale * p.vInfKips});
        yMax = std::max(yMax, cs.scale * p.vInfKips);
        cpMax = std::max(cpMax, cs.cp * p.cpPsi);
    }
    QList<QAbstractSeries*> series;
    auto* s = new QScatterSeries;
    s->replace(used);
    s->setName(QString::fromStdString(c.configuration));
    s->setColor(colour);
    series << s;
    if (!excluded.isEmpty()) {
        auto* x = new QScatterSeries;
        x->replace(excluded);
        x->setName(FrictionPanel::tr("%1 (excluded)").arg(QString::fromStdString(c.configuration)));
        x->setMarkerShape(QScatterSeries::MarkerShapeRectangle);
        x->setColor(colour.lighter(160));
        series << x;
    }
    if (c.coulomb) series << coulombLine(c, cs, colour);
    return series;
}

} // namespace

void FrictionPanel::fillCoulombChart() {
    // Fig. 21: V_inf (or tau_inf with A_b) against CP, with the least-squares line for CP <= limit.
    const ShownUnits u = shownUnits(units_);
    const bool withArea = areaIn2_ > 0.0;
    CoulombScales cs;
    cs.cp = u.pressure;
    // kips -> psi over A_b, then into the shown pressure (or force) unit.
    cs.scale = withArea ? u.pressure * 1000.0 / bearingAreaIn2() : u.force;
    cs.maxCpPsi = calibration_.options.maxCpPsi;
    cs.intercept = slopeKind_->currentIndex() == 0;
    QList<QAbstractSeries*> series;
    double yMax = 1.0, cpMax = 100.0 * u.pressure;
    int k = 0;
    for (const ConfigurationCalibration& c : calibration_.configurations)
        series << configurationSeries(c, cs, cpColor(k++), yMax, cpMax);
    coulomb_->chart()->setTitle(withArea ? tr("τ∞ = V∞ / A_b against confining pressure")
                                         : tr("V∞ against confining pressure"));
    resetChart(coulomb_->chart(), series, axis(tr("CP (%1)").arg(u.p), 0.0, 1.05 * cpMax),
               axis(withArea ? tr("τ∞ (%1)").arg(u.p) : tr("V∞ (%1)").arg(u.f), 0.0, 1.1 * yMax));
}

} // namespace kinstab::ui
