// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/ReportAnalysis.h"
#include "core/base/Stopwatch.h"
#include "report/CodeStyle.h"

#include "core/assessment/ProjectRequest.h"
#include "core/assessment/RunAssessment.h"
#include "core/codes/CodeSet.h"
#include "core/sweep/ModelPoint.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <map>

namespace kinstab::report {

namespace {

std::vector<double> linspace(double lo, double hi, int n) {
    if (n < 2) return {lo};
    std::vector<double> v(static_cast<std::size_t>(n));
    for (int k = 0; k < n; ++k)
        v[k] = lo + (hi - lo) * k / (n - 1);
    return v;
}

SurfaceData figureSweep(const ModelPoint& m, const SweepGrid& g, SweepControl* control,
                        long& runs) {
    const SweepResult r = runSweep(g, m.point, control);
    runs += static_cast<long>(r.completed);
    return surfaceFromSweep(r, m.tauRef);
}

// The map reaches down to the smallest code ratio (so the code lines and design points lie on
// it) and spans the building frequency.
SweepGrid mapGrid(const Project& p, const std::vector<CodeResult>& codes, std::optional<double> fd,
                  int n) {
    double aLo = p.grid.amplitudes.front(), aHi = p.grid.amplitudes.back();
    for (const CodeResult& r : codes)
        aLo = std::min(aLo, r.topRatio);
    aLo = std::max(0.05, std::floor(aLo * 0.8 * 20) / 20);
    double fLo = p.grid.frequencies.front(), fHi = p.grid.frequencies.back();
    if (fd) fLo = std::min(fLo, *fd), fHi = std::max(fHi, *fd);
    return {linspace(aLo, aHi, n), linspace(fLo, fHi, n)};
}

// γc(A) at the building frequency fd, up to past A_crit (the slice figure).
SliceData designSlice(const Project& project, const ModelPoint& model,
                      const DesignCheckResult& check, double fd, double step, SweepControl* control,
                      long& runs) {
    SliceData slice;
    slice.frequency = fd;
    double aCrit = 0;
    for (const CodeVerdict& v : check.codes)
        if (v.aCrit && std::abs(v.frequencyHz - fd) < 1e-12)
            aCrit = *v.aCrit, slice.aCrit = v.aCrit;
    const double hi = std::max(project.grid.amplitudes.back(), 1.25 * aCrit);
    // From one step above 0: an amplitude of 0 is no excitation at all.
    const int steps = static_cast<int>(std::ceil(hi / step));
    const SweepGrid g{linspace(hi / steps, hi, steps), {fd}};
    const SweepResult r = runSweep(g, model.point, control);
    runs += static_cast<long>(r.completed);
    const SurfaceData s = surfaceFromSweep(r, model.tauRef);
    slice.amplitudes = s.amplitudes;
    slice.gamma = s.gamma;
    return slice;
}

// A_crit(f) over the map's frequencies (the overlay of the contour map).
void criticalOverlay(AnalysisRequest request, const CriticalSearch& search, AnalysisControl& ctl,
                     ReportAnalysis& a) {
    request.parts = AnalysisParts{};
    request.parts.criticalCurve = true;
    request.criticalFrequencies = a.overlay.critFrequencies;
    request.criticalSearch = search;
    const AnalysisResult curve = runAnalysis(request, ctl);
    if (!curve.critical) return;
    a.overlay.critAmplitude = curve.critical->amplitude;
    a.critRuns = curve.critical->runs;
}

// The project's record: single run, critical peak, verdicts; a bad record is a ProjectError.
std::optional<RecordAnalysis> recordCheck(const Project& project, AnalysisRequest request,
                                          AnalysisControl& ctl) {
    request.parts = AnalysisParts{};
    request.parts.recordCheck = true;
    request.record = project.record;
    try {
        return runAnalysis(request, ctl).record;
    } catch (const RecordError& e) {
        throw ProjectError("excitation.record.file = '" + project.record->file + "': " + e.what());
    } catch (const std::invalid_argument& e) {
        throw ProjectError(e.what());
    }
}

SolverCrossCheck crossCheck(const Project& p, const SweepResult& exact, double steps) {
    SolverCrossCheck x;
    x.paperSteps = steps;
    x.exactSeconds = exact.wallTimeSeconds;
    Slab1DCase paper = p.slab;
    paper.solver = SolverKind::Paper;
    paper.paperStepsPerPeriod = steps;
    const SweepResult r = runSweep(p.grid, slab1DPoint(paper));
    x.paperSeconds = r.wallTimeSeconds;
    for (std::size_t k = 0; k < r.points.size(); ++k) {
        const PointResult& a = exact.points[k];
        const PointResult& b = r.points[k];
        const bool ca = a.outcome == Outcome::Collapsed, cb = b.outcome == Outcome::Collapsed;
        if (ca != cb) ++x.outcomeMismatch;
        if (!ca || !cb) continue;
        ++x.compared;
        x.maxRelTauDiff = std::max(x.maxRelTauDiff, std::abs(b.tauC - a.tauC) / a.tauC);
    }
    return x;
}

} // namespace

Assessment assessReport(const Project& project, const ReportAnalysis& a) {
    AssessmentParts parts;
    if (!a.check.codes.empty()) parts.sine = a.check;
    if (a.record && a.record->critical) {
        parts.record = a.record->verdicts;
        parts.recordName = a.record->ground.name;
    }
    if (a.floors) parts.floors = floorCheckParts(*a.floors, project.building.stories);
    parts.risk = a.risk;
    parts.blocks = a.blocks;
    if (a.blocks && a.record) parts.recordName = a.record->ground.name;
    return composeAssessment(project, parts);
}

std::optional<double> designFrequency(const Project& project, const DesignCheckResult& check) {
    if (project.building.period) return 1.0 / *project.building.period;
    if (!check.codes.empty()) return check.codes.front().frequencyHz;
    return std::nullopt;
}

namespace {

// The project's sine check: the surface and the design check, for the project's model.
AnalysisRequest sineRequest(const Project& project) {
    AnalysisParts parts;
    parts.surface = true;
    parts.designCheck = true;
    return analysisRequest(project, parts);
}

// The figures' own sweeps: the wireframe's net and the map, n × n points (fewer for the planar
// model, whose points cost more).
void runFigureSweeps(const Project& project, const ModelPoint& model,
                     const AnalysisOptions& options, std::optional<double> fd,
                     SweepControl* control, ReportAnalysis& a) {
    const bool planar = project.model == ModelKind::Planar;
    const int n =
        planar ? std::min(options.figureGrid, options.planarFigureGrid) : options.figureGrid;
    const auto t = std::chrono::steady_clock::now();
    const SweepGrid net{
        linspace(project.grid.amplitudes.front(), project.grid.amplitudes.back(), n),
        linspace(project.grid.frequencies.front(), project.grid.frequencies.back(), n)};
    a.netSurface = figureSweep(model, net, control, a.figureRuns);
    a.mapSurface = figureSweep(model, mapGrid(project, a.codes, fd, n), control, a.figureRuns);
    a.figureSweepSeconds = secondsSince(t);
}

// What the figures draw over the surfaces: A_crit(f) on the map's frequencies, the design
// frequency and each code's ratio.
void buildOverlay(const AnalysisRequest& request, const Project& project, std::optional<double> fd,
                  AnalysisControl& ctl, ReportAnalysis& a) {
    a.overlay.critFrequencies = a.mapSurface.frequencies;
    criticalOverlay(request, project.critical, ctl, a);
    a.overlay.designFrequency = fd;
    for (const CodeVerdict& v : a.check.codes)
        a.overlay.codes.push_back(
            {shortCodeName(v.code), v.ratio, v.frequencyHz, codeColour(v.code)});
}

// The sections beyond the sine check: the design slice, the record, floors, blocks and the
// cross-check against the paper's solver.
void runFurtherChecks(const Project& project, const AnalysisRequest& request,
                      const ModelPoint& model, const AnalysisOptions& options,
                      std::optional<double> fd, AnalysisControl& ctl, ReportAnalysis& a) {
    SweepControl* control = &ctl.sweepControl();
    if (fd)
        a.slice =
            designSlice(project, model, a.check, *fd, options.sliceStep, control, a.figureRuns);
    if (project.record) a.record = recordCheck(project, request, ctl);
    a.floors = computeReportFloors(project, control);
    if (a.record && !project.blocks.empty()) {
        a.blocks = blockCheckParts(project, a.record->ground, control);
        a.blockMaps = computeReportBlockMaps(project, control);
    }
    // The paper's RK4 solver is of the 1-DOF model only.
    if (options.crossCheck && project.slab.solver == SolverKind::Exact &&
        project.model != ModelKind::Planar)
        a.crossCheck = crossCheck(project, a.projectSweep, options.crossCheckSteps);
}

} // namespace

ReportAnalysis computeReportAnalysis(const Project& project, const AnalysisOptions& options,
                                     AnalysisControl* outside) {
    if (const std::string e = validateProject(project); !e.empty()) throw ProjectError(e);
    AnalysisControl own;
    AnalysisControl& ctl = outside ? *outside : own;
    const auto t0 = std::chrono::steady_clock::now();
    ReportAnalysis a;
    // Every sweep, A_crit search and the check below run the project's model (docs/user-guide.md).
    const AnalysisRequest request = sineRequest(project);
    const ModelPoint model = modelPoint(project.slab, request.planar);
    if (request.planar) a.planarSolver = request.planar->solver;
    a.scanFrom = model.scanFrom;
    // Before the sweeps: a bad results or hazard file is an InputError naming it, at once.
    a.risk = projectRiskParts(project);
    a.codes = request.codes;
    const AnalysisResult sine = runAnalysis(request, ctl);
    if (sine.checkError) std::rethrow_exception(sine.checkError);
    a.check = sine.check.value_or(DesignCheckResult{});
    a.checkSeconds = sine.checkSeconds;
    a.projectSweep = *sine.surface;

    const std::optional<double> fd = designFrequency(project, a.check);
    // The figure sweeps, the slice and floors share the sweep control.
    runFigureSweeps(project, model, options, fd, &ctl.sweepControl(), a);
    buildOverlay(request, project, fd, ctl, a);
    runFurtherChecks(project, request, model, options, fd, ctl, a);
    a.assessment = assessReport(project, a);
    a.totalSeconds = secondsSince(t0);
    return a;
}

} // namespace kinstab::report
