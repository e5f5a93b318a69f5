// SPDX-License-Identifier: GPL-3.0-or-later
// The report's floor-motion section (issue 19), when the project has a "floors" object and a
// record: the building as a shear building under the ground record, the peak floor
// acceleration per level against the ASCE 7-22 §13.3.1 and EN 1998-1 §4.3.5.2 demands, the
// critical PGA per level and the verdicts at the slab's level.

#include "core/assessment/RunAssessment.h"
#include "report/ComparisonTable.h"
#include "report/CurveFigure.h"
#include "report/ReportSections.h"

#include <algorithm>

namespace kinstab::report {

namespace {

const QColor kModel(0, 90, 181), kAsce(200, 60, 30), kEc8(30, 140, 60), kCrit(160, 0, 120);

const FloorDemand* demandOf(const FloorAnalysis& a, const std::string& code) {
    for (const FloorDemand& d : a.demands)
        if (d.code == code) return &d;
    return nullptr;
}

QString cell(const FloorDemand* d, bool factor, std::size_t i) {
    return d ? num(factor ? d->factor[i] : d->pfa[i], 3) : QStringLiteral("—");
}

void levelTable(ReportDocument& doc, const Project& p, const FloorAnalysis& a) {
    const FloorDemand *asce = demandOf(a, "asce7_22"), *mce = demandOf(a, "asce7_22_mce"),
                      *ec8 = demandOf(a, "ec8");
    Table t{{"level", "height (" + lengthSymbolOf(p, LengthScale::Structure) + ")", "PFA (g)",
             "PFA/PGA", "ASCE H_f", "ASCE (g)", "ASCE MCE_R (g)", "EC8 (g)", "critical PGA (g)"},
            {},
            {0.6, 0.9, 0.8, 0.8, 0.8, 0.8, 1.0, 0.8, 1.1},
            std::vector<Align>(9, Align::Right),
            {a.slabLevel - 1}};
    const std::vector<double> h = levelHeightsShown(p);
    for (std::size_t i = 0; i < a.pfa.size(); ++i) {
        const bool searched = i < a.critical.size();
        t.rows.push_back({QString::number(i + 1), num(h[i], 1), num(a.pfa[i], 3),
                          num(a.pfa[i] / a.pga, 2), cell(asce, true, i), cell(asce, false, i),
                          cell(mce, false, i), cell(ec8, false, i),
                          searched ? num(a.critical[i].criticalPga, 3, QStringLiteral("none"))
                                   : QStringLiteral("—")});
    }
    doc.addTable(t);
}

QList<QPointF> profile(const std::vector<double>& x, const std::vector<double>& h) {
    QList<QPointF> pts;
    for (std::size_t i = 0; i < x.size(); ++i)
        pts.append(QPointF(x[i], h[i]));
    return pts;
}

void profileFigure(ReportDocument& doc, const Project& p, const FloorAnalysis& a) {
    const std::vector<double> h = levelHeightsShown(p);
    double hi = std::max(a.sdofRoofPeak, *std::max_element(a.pfa.begin(), a.pfa.end()));
    for (const LevelCritical& l : a.critical)
        if (l.criticalPga) hi = std::max(hi, *l.criticalPga);
    for (const FloorDemand& d : a.demands)
        hi = std::max(hi, d.pfa.back());
    CurvePlot plot;
    plot.xhi = 1.05 * hi;
    plot.yhi = 1.4 * h.back(); // headroom above the roof keeps the legend off the curves
    plot.xLabel = QStringLiteral("acceleration (g)");
    plot.yLabel = "height (" + lengthSymbolOf(p, LengthScale::Structure) + ")";
    QList<QPointF> model = profile(a.pfa, h);
    model.prepend(QPointF(a.pga, 0.0));
    plot.curves.push_back({model, kModel, "PFA, model under the record", 0.25});
    for (const FloorDemand& d : a.demands)
        plot.curves.push_back({profile(d.pfa, h), d.code == "ec8" ? kEc8 : kAsce,
                               d.code == "ec8"            ? "PFA demand, EN 1998-1"
                               : d.code == "asce7_22_mce" ? "PFA demand, ASCE 7-22 MCE_R"
                                                          : "PFA demand, ASCE 7-22 design",
                               d.code == "asce7_22_mce" ? 0.1 : 0.2});
    std::vector<double> crit, ch;
    for (const LevelCritical& l : a.critical)
        if (l.criticalPga) {
            crit.push_back(*l.criticalPga);
            ch.push_back(h[static_cast<std::size_t>(l.level - 1)]);
        }
    plot.curves.push_back({profile(crit, ch), kCrit, "critical PGA of the record", 0.25});
    doc.addFigure(
        {[plot](QPainter& pa, const QRectF& r) { paintCurves(pa, r, plot); }, 0.62,
         QStringLiteral("Peak floor acceleration per level under the record as recorded "
                        "(PGA %1 g at the base), the codes' demands on a rigid element, and "
                        "the record's PGA at which the slab on each level falls.")
             .arg(num(a.pga, 3))});
}

void trailTable(ReportDocument& doc, const FloorDemand& d) {
    Table t{{"coefficient", "symbol", "value", "clause"},
            {},
            {2.2, 1.0, 0.8, 2.2},
            {Align::Left, Align::Left, Align::Right, Align::Left},
            {static_cast<int>(d.trail.size()) - 1}};
    for (const TrailEntry& e : d.trail)
        t.rows.push_back({qs(e.name), qs(e.symbol), coefficient(e.value), qs(e.clause)});
    doc.addHeading(qs(d.title), 2);
    doc.addTable(t);
}

} // namespace

std::optional<FloorAnalysis> computeReportFloors(const Project& p, SweepControl* control) {
    if (!p.floors || !p.record) return std::nullopt;
    FloorAnalysisInput in;
    try {
        in = floorAnalysisInput(p, readGroundRecord(*p.record));
    } catch (const RecordError& e) {
        throw ProjectError("excitation.record.file = '" + p.record->file + "': " + e.what());
    }
    if (const std::string e = validateFloorAnalysis(in); !e.empty()) throw ProjectError(e);
    FloorAnalysis a = analyseFloors(in, control);
    if (a.cancelled) return std::nullopt;
    return a;
}

void addFloorsSection(ReportDocument& doc, const Project& p, const ReportAnalysis& r) {
    if (!r.floors) return;
    const FloorAnalysis& a = *r.floors;
    doc.addSection(QStringLiteral("Floor motions and today's floor-acceleration demands"));
    doc.addParagraph(
        QStringLiteral(
            "The building as a shear building: one horizontal degree of freedom per level, "
            "storey stiffness %1, scaled so that the first period is %2 s (%3); %4 % damping in "
            "every mode, all %5 modes superposed, each with the exact recurrence for a record "
            "linear between samples (Nigam and Jennings 1969). The ground record drives the "
            "base as recorded. The paper's single-oscillator floor filter (T, same damping) "
            "gives %6 g at the roof; the model gives %7 g.")
            .arg(qs(stiffnessName(p.floors->stiffness)), num(a.building.period, 3),
                 qs(a.building.periodSource), num(100.0 * a.damping, 1))
            .arg(a.model.modes.size())
            .arg(num(a.sdofRoofPeak, 3), num(a.pfa.back(), 3)));
    profileFigure(doc, p, a);
    levelTable(doc, p, a);
    doc.addParagraph(
        QStringLiteral("Demands on a rigid element: ASCE 7-22 eq. 13.3-1 read as 0.4 S_DS H_f / "
                       "R_mu (I_p = C_AR = R_po = 1), at MCE_R with S_MS = 1.5 S_DS; EN 1998-1 "
                       "eq. 4.25 with gamma_a = q_a = 1. Critical PGA: the record's PGA at which "
                       "the slab on the level first collapses (the building is linear, so the "
                       "level's critical floor peak scales back to the ground). The slab is on "
                       "level %1 (bold row).")
            .arg(a.slabLevel),
        true);
    if (hasBasis(r.assessment, CheckBasis::Floors)) {
        doc.addHeading(QStringLiteral("Floor checks at the slab's level"), 2);
        addComparisonTable(doc, r.assessment, CheckBasis::Floors, {1.9, 2.4, 0.8, 0.8, 0.7, 1.8});
    }
    for (const FloorDemand& d : a.demands)
        trailTable(doc, d);
}

} // namespace kinstab::report
