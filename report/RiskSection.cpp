// SPDX-License-Identifier: GPL-3.0-or-later
// The report's risk section (docs/studies.md, "Risk"): each parameter set's collapse fragility
// integrated against the site's hazard curve - the annual rate of the slab falling lambda_C, the
// probability in N years, the closed forms beside it, the rule of the integral and the curve
// itself. The numbers are those of the assessment's risk checks (ReportAnalysis::risk), which
// page 1 shows with the other checks; nothing is computed here but the figure's points.

#include "core/assessment/Assessment.h"
#include "report/CurveFigure.h"
#include "report/ReportSections.h"

#include <QFileInfo>

#include <algorithm>
#include <cmath>

namespace kinstab::report {

namespace {

const QColor kHazard(40, 90, 160);

// A rate to 3 significant digits in the C locale's syntax ("2.01e-04").
QString rate(double x) {
    return QString::number(x, 'e', 2);
}

const Check* checkOf(const Assessment& a, std::size_t set) {
    const std::string id = riskCheckId(set);
    for (const Check& c : a.checks)
        if (c.id == id) return &c;
    return nullptr;
}

void riskTable(ReportDocument& doc, const RiskCheckParts& r, const Assessment& a) {
    Table t{{"set", "check", "median (g)", "β", "λ_C (1/yr)",
             QStringLiteral("P in %1 yr").arg(num(r.settings.years, 0)), "margin", "verdict"},
            {},
            {0.4, 0.9, 0.8, 0.5, 0.9, 0.8, 0.7, 2.6},
            {Align::Left, Align::Left, Align::Right, Align::Right, Align::Right, Align::Right,
             Align::Right, Align::Left},
            {}};
    for (const RiskSetPart& s : r.sets) {
        const Check* c = checkOf(a, s.parameters.set);
        const QString set = QString::number(s.parameters.set + 1);
        if (!s.risk || !c) {
            t.rows.push_back({set, qs(riskCheckId(s.parameters.set)), "—", "—", "—", "—", "—",
                              QStringLiteral("not checked: %1").arg(qs(s.noFit))});
            continue;
        }
        const RiskResult& x = *s.risk;
        t.rows.push_back({set, qs(c->id), accelG(x.fragility.medianG), num(x.fragility.beta, 3),
                          rate(x.integral.lambdaC), QString::number(x.pInYears, 'f', 4),
                          qs(marginText(c->governing())), qs(c->verdict)});
    }
    doc.addTable(t);
}

QString formCell(const std::string& why, double lambda) {
    return why.empty() ? rate(lambda) : QStringLiteral("n/a");
}

void closedFormTable(ReportDocument& doc, const RiskCheckParts& r) {
    Table t{{"set", "λ_C rule (1/yr)", "within curve", "beyond x_max", "1st order (k)", "2nd order",
             "x at P(C) = 10 % (g)", "median for target (g)"},
            {},
            {0.4, 0.9, 0.9, 0.9, 1.2, 0.9, 1.0, 1.1},
            {Align::Left, Align::Right, Align::Right, Align::Right, Align::Right, Align::Right,
             Align::Right, Align::Right},
            {}};
    bool notApplied = false;
    for (const RiskSetPart& s : r.sets) {
        if (!s.risk) continue;
        const RiskResult& x = *s.risk;
        notApplied = notApplied || !x.firstOrder.why.empty() || !x.secondOrder.why.empty();
        t.rows.push_back(
            {QString::number(s.parameters.set + 1), rate(x.integral.lambdaC),
             rate(x.integral.withinCurve), rate(x.integral.beyondLastPoint),
             formCell(x.firstOrder.why, x.firstOrder.lambdaC) +
                 (x.firstOrder.why.empty() ? QStringLiteral(" (%1)").arg(num(x.firstOrder.k, 2))
                                           : QString()),
             formCell(x.secondOrder.why, x.secondOrder.lambdaC), accelG(x.imAtTenPercent),
             x.targeted.medianG ? accelG(*x.targeted.medianG) : QStringLiteral("—")});
    }
    if (t.rows.empty()) return;
    doc.addTable(t);
    if (notApplied)
        doc.addParagraph(QStringLiteral("n/a: the closed form does not apply (the median lies "
                                        "outside the curve, or the fit diverges); kinstab-cli "
                                        "risk states why."),
                         true);
}

// The hazard curve in log10-log10 axes (the report's plots are linear: a power law is then a
// straight line, and decades of rate stay readable), with the target rate as a level.
CurvePlot hazardPlot(const RiskCheckParts& r, const QString& measure) {
    const std::vector<HazardPoint>& pts = r.curve.points;
    CurvePlot plot;
    plot.xLabel = QStringLiteral("log10 %1 (g)").arg(measure);
    plot.yLabel = QStringLiteral("log10 annual rate of exceedance");
    QList<QPointF> curve;
    for (const HazardPoint& q : pts)
        curve.append(QPointF(std::log10(q.imG), std::log10(q.annualRate)));
    plot.xlo = std::floor(curve.front().x());
    plot.xhi = std::ceil(curve.back().x());
    plot.ylo = std::floor(std::min(curve.back().y(), std::log10(r.settings.targetRate)) - 0.5);
    plot.yhi = std::ceil(curve.front().y());
    plot.curves.push_back({curve, kHazard, QStringLiteral("hazard curve λ(x)"), 0.3});
    QList<QPointF> target = {QPointF(plot.xlo, std::log10(r.settings.targetRate)),
                             QPointF(plot.xhi, std::log10(r.settings.targetRate))};
    plot.curves.push_back(
        {target, QColor(120, 120, 120),
         QStringLiteral("target rate %1 per year").arg(rate(r.settings.targetRate)), 0.15});
    return plot;
}

void hazardFigure(ReportDocument& doc, const RiskCheckParts& r) {
    if (r.curve.points.size() < 2) return;
    const QString measure = qs(hazardMeasureName(r.curve.measure));
    const CurvePlot plot = hazardPlot(r, measure);
    doc.addFigure({[plot](QPainter& pa, const QRectF& area) { paintCurves(pa, area, plot); }, 0.5,
                   QStringLiteral("The site's hazard curve (%1, %2 points, %3 file), in "
                                  "log10-log10 axes: the annual rate at which %4 exceeds x, "
                                  "and the target rate of collapse.")
                       .arg(QFileInfo(qs(r.hazard.file)).fileName())
                       .arg(r.curve.points.size())
                       .arg(qs(r.curve.format), measure)});
}

} // namespace

void addRiskSection(ReportDocument& doc, const Project& p, const ReportAnalysis& a) {
    if (!p.study || !p.study->hazard) return;
    doc.addSection(QStringLiteral("Risk: annual rate of the slab falling"));
    if (!a.risk) {
        doc.addParagraph(QStringLiteral("The study names the hazard curve %1, but the project "
                                        "names no results of the study (study.results, written "
                                        "by kinstab-cli study); the risk is computed from "
                                        "them, so no risk check ran.")
                             .arg(QFileInfo(qs(p.study->hazard->file)).fileName()));
        return;
    }
    const RiskCheckParts& r = *a.risk;
    const HazardPoint& lo = r.curve.points.front();
    const HazardPoint& hi = r.curve.points.back();
    doc.addParagraph(
        QStringLiteral(
            "Each parameter set's lognormal collapse fragility (the study section's fit, "
            "P(C | x) = Φ(ln(x/θ)/β)) is integrated against the site's hazard curve %1 (%2, "
            "%3 points from %4 g at %5 per year to %6 g at %7 per year): λ_C = ∫ P(C | x) "
            "|dλ(x)|, the annual rate at which the slab slides off its walls, and the probability "
            "of at least one collapse in %8 years, 1 − exp(−%8 λ_C). Each set's risk check "
            "(risk.setK on page 1) compares λ_C with the target rate %9, margin = target / λ_C.")
            .arg(QFileInfo(qs(r.hazard.file)).fileName(), qs(hazardMeasureName(r.curve.measure)))
            .arg(r.curve.points.size())
            .arg(num(lo.imG, 3), rate(lo.annualRate), num(hi.imG, 3), rate(hi.annualRate))
            .arg(num(r.settings.years, 0))
            .arg(QStringLiteral("%1 per year (%2)")
                     .arg(rate(r.settings.targetRate), qs(riskTargetText(r.settings)))));
    doc.addParagraph(
        QStringLiteral(
            "The rule, which alone moves published results by percent to tens of percent: the "
            "curve is linear in log-log between its points and each segment is integrated in "
            "closed form (no quadrature error); the rate beyond the last point, λ(x_max), counts "
            "with P(C | x_max); intensities below the first point add nothing. The closed forms "
            "are cross-checks: first order (Cornell et al. 2002, a power law fitted near the "
            "median, slope k) and second order (Vamvatsikos 2013, a quadratic in log-log)."),
        true);
    if (r.curve.zeroRatePointsDropped > 0)
        doc.addParagraph(QStringLiteral("%1 points with a rate of 0 at the top of the curve end "
                                        "it at the last positive rate.")
                             .arg(r.curve.zeroRatePointsDropped),
                         true);
    doc.addHeading(QStringLiteral("Annual rate of collapse per parameter set"), 2);
    riskTable(doc, r, a.assessment);
    doc.addHeading(QStringLiteral("The rule's parts and the closed forms"), 2);
    closedFormTable(doc, r);
    hazardFigure(doc, r);
}

QStringList riskCitations(const ReportAnalysis& a) {
    if (!a.risk) return {};
    return {
        QStringLiteral("C. A. Cornell, F. Jalayer, R. O. Hamburger, D. A. Foutch, "
                       "Probabilistic basis for 2000 SAC Federal Emergency Management Agency "
                       "steel moment frame guidelines, J. Struct. Eng. 128(4), 2002 (first-order "
                       "closed form of the risk integral)."),
        QStringLiteral("D. Vamvatsikos, Derivation of new SAC/FEMA performance evaluation "
                       "solutions with second-order hazard approximation, Earthquake Engng "
                       "Struct. Dyn. 42, 2013 (second-order closed form).")};
}

} // namespace kinstab::report
