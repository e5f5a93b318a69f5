// SPDX-License-Identifier: GPL-3.0-or-later
// The γc surface figures, the slice at the building frequency, the verdicts, the numerics and
// the references.
#include "core/codes/CodeCatalog.h"
#include "core/codes/CodeSet.h"
#include "core/slab/VerticalRecord.h"
#include "report/ContourFigure.h"
#include "report/RecordSources.h"
#include "report/ReportSections.h"
#include "report/SliceFigure.h"
#include "report/WireframeFigure.h"

#include <cmath>
#include <map>

namespace kinstab::report {

namespace {

QString envelopeWords(const Envelope& e) {
    return e.preset
               ? qs(presetName(*e.preset)) + " envelope"
               : QStringLiteral("envelope α = %1, β = %2 1/s").arg(num(e.alpha, 3), num(e.beta, 3));
}

// γc on the project's grid as a table: one row per amplitude, one column per frequency.
Table gammaTable(const Project& p, const ReportAnalysis& a) {
    const SweepResult& r = a.projectSweep;
    const std::vector<double> g = collapseFactors(r, p.slab.tauRef());
    Table t;
    t.header << QStringLiteral("A (g) \\ f (Hz)");
    for (double f : r.grid.frequencies)
        t.header << num(f, 3);
    t.columnWeights.assign(t.header.size(), 1.0);
    t.align.assign(t.header.size(), Align::Right);
    t.align[0] = Align::Left;
    for (std::size_t i = 0; i < r.grid.amplitudes.size(); ++i) {
        QStringList row{num(r.grid.amplitudes[i], 3)};
        for (std::size_t j = 0; j < r.grid.frequencies.size(); ++j) {
            const std::size_t k = i * r.grid.frequencies.size() + j;
            const PointResult& pt = r.points[k];
            if (!r.done[k])
                row << QStringLiteral("not run");
            else if (pt.outcome == Outcome::Collapsed)
                row << num(g[k], 4);
            else
                row << qs(outcomeName(pt.outcome));
        }
        t.rows.push_back(row);
    }
    return t;
}

// What γc means and which model, case and envelope the surfaces are of.
QString surfaceIntro(const Project& p, const QString& env) {
    return QStringLiteral(
               "γc = τ_ref / τc, with τc the dimensionless time at which the slab slides off its "
               "walls "
               "(|δ| > %1) and τ_ref = %2 = %3; γc = 0 where the slab stays on (stable). Larger γc "
               "means an earlier collapse, a greater hazard. Model: %7, μ = %4, t* = %5 s, "
               "%6.")
        .arg(num(p.slab.slab.limit, 2), scaleLabel(p.slab.scale), num(p.slab.tauRef(), 2),
             num(p.slab.slab.mu, 3), num(p.slab.tstar, 4), env,
             p.model == ModelKind::Planar
                 ? QStringLiteral("planar slab, f_y = %1 Hz, A_y/A_x = %2")
                       .arg(num(p.planar.fyHz, 3), num(p.planar.ayRatio, 3))
                 : QStringLiteral("1-DOF slab"));
}

void addWireframe(ReportDocument& doc, const ReportAnalysis& a, const QString& gl,
                  const QString& env) {
    const SurfaceData net = a.netSurface;
    const DesignOverlay ov = a.overlay;
    doc.addFigure(
        {[net, ov, gl](QPainter& pa, const QRectF& r) { paintWireframe(pa, r, net, ov, gl); }, 0.68,
         QStringLiteral(
             "Surface %1 over A and f (%2×%3 grid, %4), drawn as the "
             "paper's Figs. 28–33: lines parallel to the A and f axes follow "
             "the surface. Red: A_crit(f) on the floor (γc = 0) plane, drawn over the net.")
             .arg(gl)
             .arg(net.amplitudes.size())
             .arg(net.frequencies.size())
             .arg(env)});
}

void addContourMap(ReportDocument& doc, const ReportAnalysis& a, const QString& gl) {
    const SurfaceData map = a.mapSurface;
    const DesignOverlay ov = a.overlay;
    doc.addFigure(
        {[map, ov, gl](QPainter& pa, const QRectF& r) { paintContourMap(pa, r, map, ov, gl); },
         0.66,
         QStringLiteral("Filled contours of %1 (%2×%3 grid). Black: A_crit(f), "
                        "the smallest amplitude that collapses the slab. Dashed: the "
                        "codes' top-floor ratios at A = F_top/w_top; dots: design points "
                        "(F_top/w_top, 1/T); dotted: the building frequency.")
             .arg(gl)
             .arg(map.amplitudes.size())
             .arg(map.frequencies.size())});
}

// The slice at the building frequency, when there is one.
void addSliceFigure(ReportDocument& doc, const ReportAnalysis& a, const QString& gl) {
    if (a.slice.amplitudes.empty()) return;
    doc.addHeading(
        QStringLiteral("Slice at the building frequency f = %1 Hz").arg(num(a.slice.frequency, 3)),
        2);
    const SliceData slice = a.slice;
    std::vector<CodeMark> marks = a.overlay.codes;
    doc.addFigure(
        {[slice, marks, gl](QPainter& pa, const QRectF& r) { paintSlice(pa, r, slice, marks, gl); },
         0.5,
         QStringLiteral("%1 against A at f = %2 Hz (ΔA = %3 g), as the paper's "
                        "Fig. 34: zero up to A_crit, then a steep rise. Code ratios dashed.")
             .arg(gl, num(slice.frequency, 3),
                  num(slice.amplitudes.size() > 1 ? slice.amplitudes[1] - slice.amplitudes[0] : 0,
                      3))});
}

} // namespace

void addSurfaceSections(ReportDocument& doc, const Project& p, const ReportAnalysis& a) {
    const QString gl = qs(gammaScaleLabel(p.slab.scale));
    const QString env = envelopeWords(p.slab.envelope);
    doc.addSection(QStringLiteral("Collapse factor γc(A, f)"));
    doc.addParagraph(surfaceIntro(p, env));
    addWireframe(doc, a, gl, env);
    addContourMap(doc, a, gl);
    doc.addHeading(QStringLiteral("γc on the project grid"), 2);
    doc.addTable(gammaTable(p, a));
    addSliceFigure(doc, a, gl);
}

void addCodeCriticalTable(ReportDocument& doc, const ReportAnalysis& a) {
    const std::vector<CodeVerdict>& codes = a.check.codes;
    Table t{{"code", "F_top/w_top", "f = 1/T (Hz)", "A_crit (g)"},
            {},
            {2.6, 1.2, 1.2, 1.2},
            {Align::Left, Align::Right, Align::Right, Align::Right},
            {}};
    for (const CodeVerdict& v : codes) {
        QString ratio = num(v.ratio, 3);
        if (v.ratioWithoutFt) ratio = num(*v.ratioWithoutFt, 3) + " / " + ratio;
        t.rows.push_back({qs(v.title), ratio, num(v.frequencyHz, 3), accelG(v.aCrit, "> limit")});
    }
    doc.addTable(t);
    bool ubc = false;
    for (const CodeVerdict& v : codes)
        ubc = ubc || v.ratioWithoutFt.has_value();
    if (ubc)
        doc.addParagraph(
            QStringLiteral(
                "UBC ratios are given as \"without F_t / with F_t\": the paper's 0.140 leaves the "
                "top-floor whip force F_t out; the code adds it to the top floor. The verdict and "
                "margin use the ratio the code requires (with F_t)."),
            true);
}

QString solverDescription(const Project& p, const ReportAnalysis& a) {
    if (a.planarSolver)
        return QStringLiteral("numerically integrated planar model: adaptive Dormand–Prince 5(4) "
                              "steps, events located on brackets; tolerance %1 relative, %2 "
                              "absolute")
            .arg(QString::number(a.planarSolver->relTol, 'g', 3),
                 QString::number(a.planarSolver->absTol, 'g', 3));
    if (p.slab.solver == SolverKind::Exact)
        return QStringLiteral("event-driven exact solver: closed-form motion between events, "
                              "events located to ~1e-13 by bracketing and a safeguarded root "
                              "finder");
    return QStringLiteral("paper's RK4 solver, H = T/%1").arg(num(p.slab.paperStepsPerPeriod, 0));
}

void addNumericsSection(ReportDocument& doc, const Project& p, const ReportAnalysis& a) {
    doc.addSection(QStringLiteral("Appendix: numerics"));
    doc.addParagraph(QStringLiteral(
        "How the numbers of this report were computed and how accurate they are. Run times "
        "and counts of solver runs are in the JSON output of kinstab-cli report."));
    const SweepResult& r = a.projectSweep;
    std::map<Outcome, std::size_t> count;
    for (std::size_t k = 0; k < r.points.size(); ++k)
        if (r.done[k]) ++count[r.points[k].outcome];
    const std::size_t other = count[Outcome::LiftOff] + count[Outcome::Failed];
    Table t{{"item", "value"}, {}, {2.2, 3}, {}, {}};
    t.rows.push_back({"solver", solverDescription(p, a)});
    t.rows.push_back(
        {"A_crit search",
         QStringLiteral("scan from max(%1, %2) g (%3) in steps of %4 g up to %5 g, then "
                        "bisection to %6 g")
             .arg(num(a.scanFrom, 4), num(p.critical.from, 2),
                  a.planarSolver ? QStringLiteral("below the first: no slip in the planar model")
                                 : QStringLiteral("the first is μ: below it nothing slips"),
                  num(p.critical.scanStep, 4), num(p.critical.to, 2),
                  num(p.critical.tolerance, 6))});
    t.rows.push_back({"accuracy of A_crit",
                      QStringLiteral("within %1 g of the smallest collapsing peak on the scan "
                                     "(bisection tolerance); printed to 0.001 g")
                          .arg(QString::number(p.critical.tolerance, 'g', 3))});
    if (a.crossCheck) {
        const SolverCrossCheck& x = *a.crossCheck;
        t.rows.push_back(
            {"cross-check: estimated τc error",
             QStringLiteral("max |Δτc|/τc = %1 between the exact solver and the paper's RK4 at H = "
                            "T/%2 on the %3 collapsed grid points; %4 points differ in outcome")
                 .arg(QString::number(x.maxRelTauDiff, 'e', 2), num(x.paperSteps, 0))
                 .arg(x.compared)
                 .arg(x.outcomeMismatch)});
    }
    t.rows.push_back({"outcomes on the project grid",
                      QStringLiteral("%1 collapsed, %2 stable, %3 other (lift-off or failed)")
                          .arg(count[Outcome::Collapsed])
                          .arg(count[Outcome::Stable])
                          .arg(other)});
    doc.addTable(t);
}

void addCheckSection(ReportDocument& doc, const Project& p, const ReportAnalysis& a) {
    if (a.check.codes.empty()) return;
    const CheckBasis basis = p.model == ModelKind::Planar ? CheckBasis::Planar : CheckBasis::Sine;
    doc.addSection(QStringLiteral("Design check with the enveloped sine"));
    doc.addParagraph(
        QStringLiteral(
            "Chapter V of the source report: below A_crit the structure reaches its code strength "
            "first (member overstress governs); at or above it the slab slides off (kinetic "
            "instability governs). Margin = A_crit / (F_top/w_top). Each code's margin and verdict "
            "are the %1.CODE checks of the assessment on page 1; A_crit at each code's frequency:")
            .arg(qs(checkBasisName(basis))));
    addCodeCriticalTable(doc, a);
}

void addReferences(ReportDocument& doc, const Project& p, const ReportAnalysis& a) {
    doc.addSection(QStringLiteral("References"));
    QStringList refs{QStringLiteral(
        "R. L. Furgerson, Seismic Stability of Block Structures, Report AMES TR-80/002, "
        "University of California, San Diego, 1980 (model, envelopes, Table 4, chapter V "
        "example).")};
    for (const CodeInfo& c : codeCatalog())
        if (isSelected(p.codes, c.id)) refs << QString::fromUtf8(c.citation);
    if (p.record && a.record) refs << recordCitation(a.record->ground, qs(p.record->file));
    if (p.model == ModelKind::Planar && p.planar.vertical != VerticalSource::None) {
        if (const std::optional<Accelerogram> v = loadVerticalRecord(p.planar))
            refs << recordCitation(*v, p.planar.vertical == VerticalSource::Rsn68Up
                                           ? QString::fromUtf8(kRsn68UpSource)
                                           : qs(p.planar.verticalPath));
    }
    refs << studyCitations(p);
    refs << riskCitations(a);
    refs << blockCitations(a);
    for (int k = 0; k < refs.size(); ++k)
        doc.addParagraph(QStringLiteral("[%1]  %2").arg(k + 1).arg(refs[k]), true);
}

} // namespace kinstab::report
