// SPDX-License-Identifier: GPL-3.0-or-later
// Inputs, building-code trails and the excitation: what the engineer entered and what the
// codes made of it.
#include "core/excitation/EnvelopedSine.h"
#include "report/InputLabels.h"
#include "report/QuantityTable.h"
#include "report/ReportSections.h"
#include "report/SliceFigure.h"

#include <cmath>

namespace kinstab::report {

QString num(double x, int digits) {
    return QString::number(x, 'f', digits);
}

QString num(const std::optional<double>& x, int digits, const QString& none) {
    return x ? num(*x, digits) : none;
}

QString lengthSymbolOf(const Project& p, LengthScale scale) {
    return qs(lengthUnitSymbol(projectUnits(p), scale));
}

QString lengthOf(const Project& p, double metres, LengthScale scale) {
    return qs(lengthText(metres, projectUnits(p), scale));
}

double buildingMetres(const Building& b, double v) {
    return b.unit == LengthUnit::Feet ? v * kMetresPerFoot : v;
}

std::vector<double> levelHeightsShown(const Project& p) {
    std::vector<double> h = levelHeights(p.building);
    const double perShown = metresPerUnit(projectUnits(p), LengthScale::Structure);
    for (double& x : h)
        x = buildingMetres(p.building, x) / perShown;
    return h;
}

QString accelG(double g) {
    return num(g, 3);
}

QString accelG(const std::optional<double>& g, const QString& none) {
    return g ? accelG(*g) : none;
}

QString coefficient(double x) {
    return QString::number(x, 'g', 4);
}

// "τ_max (peak of the envelope)" for the stored key tau_max.
QString scaleLabel(TauScale s) {
    switch (s) {
    case TauScale::TauRise:
        return QStringLiteral("τ_rise (envelope first at half its peak)");
    case TauScale::TauMax:
        return QStringLiteral("τ_max (peak of the envelope)");
    case TauScale::TauDur:
        return QStringLiteral("τ_dur (envelope last at half its peak)");
    case TauScale::One:
        return QStringLiteral("1 (τc unscaled)");
    }
    return {};
}

namespace {

QString listText(const std::vector<double>& v, const QString& unit) {
    if (v.empty()) return QStringLiteral("—");
    if (v.size() == 1) return num(v.front(), 4) + " " + unit;
    return QStringLiteral("%1 … %2 %3 (%4 values)")
        .arg(num(v.front(), 4), num(v.back(), 4), unit)
        .arg(v.size());
}

// "as entered (n)" for per-story values given, "all equal" when left out.
QString perStory(const std::vector<double>& v) {
    return v.empty() ? QStringLiteral("all equal")
                     : QStringLiteral("as entered (%1)").arg(v.size());
}

Table buildingTable(const Project& p) {
    const Building& b = p.building;
    const QString u = lengthSymbolOf(p, LengthScale::Structure);
    auto len = [&](double v) { return lengthOf(p, buildingMetres(b, v), LengthScale::Structure); };
    Table t = quantityTable();
    t.rows.push_back({"name", "", qs(b.name.empty() ? p.name : b.name), ""});
    t.rows.push_back({"stories", "n", QString::number(b.stories), ""});
    t.rows.push_back({"height of the roof above the base", "h_n", len(b.height), u});
    t.rows.push_back({"plan dimension parallel to the force", "D", len(b.planDimension), u});
    t.rows.push_back({"fundamental period", "T",
                      b.period ? num(*b.period, 3) : QStringLiteral("each code's formula"), "s"});
    t.rows.push_back({"lateral system", "", systemLabel(b.system), ""});
    t.rows.push_back({"occupancy", "", occupancyLabel(b.occupancy), ""});
    t.rows.push_back({"story weights", "w_i", perStory(b.storyWeights), ""});
    t.rows.push_back(
        {"story heights", "h_i", perStory(b.storyHeights), b.storyHeights.empty() ? QString() : u});
    return t;
}

// The solver that ran: the planar model is integrated numerically whatever slab.solver says.
QString solverText(const Slab1DCase& s, const ReportAnalysis& a) {
    if (a.planarSolver)
        return QStringLiteral("numerical (Dormand–Prince 5(4), tolerance %1)")
            .arg(QString::number(a.planarSolver->relTol, 'g', 3));
    if (s.solver == SolverKind::Exact)
        return QStringLiteral("exact (event-driven, closed form between events)");
    return QStringLiteral("the paper's RK4, H = T/%1").arg(num(s.paperStepsPerPeriod, 0));
}

// The wall beside the time it sets: t* = √(d/2g), so d = 2g·t*² when only t* was entered.
// In the project's units, to 0.1 mm or 0.01 in: a 150 mm wall prints as 150 mm.
QStringList wallRow(const Project& p) {
    const double dM =
        p.wallWidthIn ? *p.wallWidthIn * kMetresPerInch : wallWidthFromTstar(p.slab.tstar);
    return {p.wallWidthIn ? "wall width" : "wall width (from t*: d = 2g·t*²)", "d",
            lengthOf(p, dM, LengthScale::Detail), lengthSymbolOf(p, LengthScale::Detail)};
}

Table slabTable(const Project& p, const ReportAnalysis& a) {
    const Slab1DCase& s = p.slab;
    Table sl = quantityTable();
    sl.rows.push_back({"model", "",
                       p.model == ModelKind::Planar ? "planar 2-DOF slab" : "1-DOF slab (ch. IV)",
                       ""});
    sl.rows.push_back({"friction coefficient", "μ", num(s.slab.mu, 3), ""});
    sl.rows.push_back(wallRow(p));
    sl.rows.push_back({"characteristic time √(d/2g)", "t*", num(s.tstar, 4), "s"});
    sl.rows.push_back(
        {"bearing length / (d/2): collapse limit", "|δ| >", num(s.slab.limit, 3), ""});
    sl.rows.push_back({"earthquake duration cap", "τ_out",
                       s.slab.duration ? num(*s.slab.duration, 1) : QStringLiteral("none"), ""});
    sl.rows.push_back({"solver", "", solverText(s, a), ""});
    sl.rows.push_back(
        {"collapse-factor scaling", "τ_ref", scaleLabel(s.scale) + " = " + num(s.tauRef(), 2), ""});
    sl.rows.push_back({"sweep amplitudes", "A", listText(p.grid.amplitudes, "g"), ""});
    sl.rows.push_back({"sweep frequencies", "f", listText(p.grid.frequencies, "Hz"), ""});
    sl.rows.push_back({"A_crit search: scan step, tolerance", "",
                       num(p.critical.scanStep, 4) + ", " + num(p.critical.tolerance, 6), "g"});
    sl.rows.push_back({"A_crit search: limit", "", num(p.critical.to, 2), "g"});
    return sl;
}

} // namespace

void addInputSections(ReportDocument& doc, const Project& p, const ReportAnalysis& a) {
    doc.addSection(QStringLiteral("Inputs"));
    doc.addHeading(QStringLiteral("Building"), 2);
    doc.addTable(buildingTable(p));
    if (!p.codes.empty()) {
        doc.addHeading(QStringLiteral("Code inputs"), 2);
        doc.addTable(codeInputsTable(p.codes));
    }
    doc.addHeading(QStringLiteral("Slab, wall and analysis"), 2);
    doc.addTable(slabTable(p, a));
    addPlanarInputs(doc, p);
}

void addCodeSections(ReportDocument& doc, const Project& p, const ReportAnalysis& a) {
    if (a.codes.empty()) return;
    (void)p;
    doc.addSection(QStringLiteral("Building codes: top-floor force ratio"));
    doc.addParagraph(QStringLiteral(
        "Each code gives the base shear and its distribution over the height; the top floor "
        "carries the largest lateral force per unit weight, F_top / w_top. That ratio is the "
        "floor acceleration (in g) that the code requires the structure to resist; the checks "
        "on page 1 compare it with the slab's critical floor peak (A_crit, or a record's "
        "critical peak)."));
    for (const CodeResult& r : a.codes) {
        doc.addHeading(qs(r.title), 2);
        Table t{{"coefficient", "symbol", "value", "source"},
                {},
                {3, 1.2, 1.4, 3.4},
                {Align::Left, Align::Left, Align::Right, Align::Left},
                {}};
        // Ratios as everywhere else in the report (0.140, not 0.14); other coefficients as given.
        for (const TrailEntry& e : r.trail)
            t.rows.push_back({qs(e.name), qs(e.symbol),
                              qs(e.name).contains(QStringLiteral("ratio")) ? accelG(e.value)
                                                                           : coefficient(e.value),
                              qs(e.clause)});
        t.rows.push_back(
            {"period used", "T", coefficient(r.periodSeconds) + " s", qs(r.periodSource)});
        if (r.topRatioWithoutFt) {
            t.rows.push_back({"top-floor ratio without F_t (the paper's eq. 14)", "F_n/w_n",
                              accelG(*r.topRatioWithoutFt), "F_t left out of the top floor"});
            t.boldRows.push_back(static_cast<int>(t.rows.size()) - 1);
            t.rows.push_back({"top-floor ratio with F_t (as the code requires)", "F_n/w_n",
                              accelG(r.topRatio), "F_t added to the top floor"});
        } else {
            t.rows.push_back({"top-floor ratio", "F_n/w_n", accelG(r.topRatio), ""});
        }
        t.boldRows.push_back(static_cast<int>(t.rows.size()) - 1);
        doc.addTable(t);
        if (!r.applicable)
            doc.addParagraph(QStringLiteral("Outside this method's applicability limits."), true);
        for (const std::string& n : r.notes)
            doc.addParagraph("Note: " + qs(n), true);
    }
}

namespace {

Table envelopeTable(const Slab1DCase& c) {
    const Envelope& e = c.envelope;
    Table t = quantityTable(QStringLiteral("parameter"));
    t.rows.push_back({"envelope decay rate", "α", num(e.alpha, 4), "1/s"});
    t.rows.push_back({"envelope rise rate", "β", num(e.beta, 4), "1/s"});
    t.rows.push_back({"characteristic time", "t*", num(c.tstar, 4), "s"});
    return t;
}

// The characteristic times γc is scaled with beside those computed from α and β.
Table timesTable(bool preset, const CharacteristicTimes& used, const CharacteristicTimes& comp) {
    Table times{{"time (τ = t/t*)", preset ? "Table 4 (used for γc)" : "used for γc",
                 "computed from α, β", "differ"},
                {},
                {2, 2, 2, 1},
                {Align::Left, Align::Right, Align::Right, Align::Left},
                {}};
    auto row = [&](const QString& name, double u, double computed) {
        const bool differ = std::abs(u - computed) > 0.005 * std::max(1.0, std::abs(u));
        times.rows.push_back({name, num(u, 2), num(computed, 2), differ ? "yes" : "no"});
    };
    row(QStringLiteral("τ_rise (first half maximum)"), used.tauRise, comp.tauRise);
    row(QStringLiteral("τ_max (peak of e)"), used.tauMax, comp.tauMax);
    row(QStringLiteral("τ_dur (second half maximum)"), used.tauDur, comp.tauDur);
    return times;
}

// a(t)/A and e(t)/S_max at frequency f over the envelope's duration and a little more
// (10 s to 120 s), 3001 samples.
ExcitationPlot excitationPlot(const Slab1DCase& c, double f, double tauDur) {
    const EnvelopedSine sine(c.envelope, 1.0, f, c.tstar);
    ExcitationPlot plot;
    const double tEnd = std::min(120.0, std::max(10.0, 2.2 * tauDur * c.tstar));
    for (int k = 0; k <= 3000; ++k) {
        const double t = tEnd * k / 3000.0;
        plot.timeSeconds.push_back(t);
        plot.accel.push_back(sine.accel(t / c.tstar));
        plot.envelope.push_back(sine.envelopeAt(t / c.tstar) / sine.sMax());
    }
    plot.title = QStringLiteral("f = %1 Hz, S_max = %2").arg(num(f, 3), num(sine.sMax(), 5));
    return plot;
}

void addExcitationIntro(ReportDocument& doc, const Project& p) {
    if (p.record)
        doc.addParagraph(QStringLiteral(
            "The project's excitation is a record (section \"Recorded excitation\"), on which the "
            "verdict rests. The enveloped sine below gives the γc surfaces, A_crit(f) and the "
            "secondary design check, for comparison."));
    doc.addParagraph(
        QStringLiteral(
            "Enveloped sine floor acceleration (Furgerson 1980, ch. IV): a(τ) = (A / S_max) · "
            "e(t*τ) · sin(ωτ), e(t) = exp(−αt) − exp(−βt), ω = 2π f t*, τ = t / t*, with S_max the "
            "largest |e(t*τ) sin(ωτ)|, so that A is the peak floor acceleration in g. Envelope: "
            "%1.")
            .arg(qs(p.slab.envelope.name())));
}

} // namespace

void addExcitationSection(ReportDocument& doc, const Project& p, const ReportAnalysis& a) {
    const Slab1DCase& c = p.slab;
    const Envelope& e = c.envelope;
    doc.addSection(QStringLiteral("Excitation"));
    addExcitationIntro(doc, p);
    const CharacteristicTimes comp = e.computedTimes(c.tstar);
    doc.addTable(envelopeTable(c));
    doc.addTable(timesTable(e.preset.has_value(), e.scalingTimes(c.tstar), comp));
    if (e.preset)
        doc.addParagraph(QStringLiteral("The paper does not print α and β; the preset values "
                                        "reproduce Table 4's τ_rise and "
                                        "τ_dur, but the peak of e falls at the computed τ_max. As "
                                        "in the paper's figures, γc "
                                        "is scaled with Table 4's printed values."),
                         true);

    const std::optional<double> fd = a.overlay.designFrequency;
    if (!fd) return;
    const ExcitationPlot plot = excitationPlot(c, *fd, comp.tauDur);
    doc.addFigure({[plot](QPainter& pa, const QRectF& r) { paintExcitation(pa, r, plot); }, 0.42,
                   QStringLiteral("Floor acceleration a(t)/A at the building frequency "
                                  "f = %1 Hz (grey) and its envelope ±e(t)/S_max (red).")
                       .arg(num(*fd, 3))});
}

} // namespace kinstab::report
