// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/ReportAnalysis.h"

#include "core/codes/CodeCatalog.h"

#include "core/codes/CodeSet.h"
#include "core/sweep/CriticalAmplitude.h"
#include "core/sweep/ModelPoint.h"
#include "report/PlanarVertical.h"

#include <QtConcurrent/QtConcurrentMap>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

namespace kinstab::ui::report {

namespace {

double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

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

std::vector<std::optional<double>> criticalCurve(const ModelPoint& m, const CriticalSearch& s,
                                                 const std::vector<double>& freqs, long& runs) {
    const std::vector<CriticalResult> found =
        QtConcurrent::blockingMapped<std::vector<CriticalResult>>(
            freqs, [&](double f) { return criticalAmplitude(m.point, f, m.scanFrom, s); });
    std::vector<std::optional<double>> out;
    for (const CriticalResult& r : found) {
        runs += r.runs;
        out.push_back(r.amplitude);
    }
    return out;
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

QString shortCodeName(const std::string& key) {
    const CodeInfo* c = findCode(key);
    return c ? QString::fromUtf8(c->shortName) : QString::fromStdString(key);
}

std::optional<double> designFrequency(const Project& project, const DesignCheckResult& check) {
    if (project.building.period) return 1.0 / *project.building.period;
    if (!check.codes.empty()) return check.codes.front().frequencyHz;
    return std::nullopt;
}

ReportAnalysis computeReportAnalysis(const Project& project, const AnalysisOptions& options,
                                     SweepControl* control) {
    if (const std::string e = validateProject(project); !e.empty()) throw ProjectError(e);
    const auto t0 = std::chrono::steady_clock::now();
    ReportAnalysis a;
    const Slab1DCase& c = project.slab;
    const bool planar = project.model == "planar";
    // Every sweep, A_crit search and the check below run the project's model (docs/user-guide.md).
    const std::optional<PlanarCase> planarCase =
        planar ? std::optional(projectPlanarCase(c, project.planar)) : std::nullopt;
    const ModelPoint model = modelPoint(c, planarCase);
    if (planarCase) a.planarSolver = planarCase->solver;
    a.scanFrom = model.scanFrom;
    a.codes = runCodes(project.building, project.codes);
    auto t = std::chrono::steady_clock::now();
    a.check = designCheck(a.codes, c, project.critical, model.point, model.scanFrom);
    a.checkSeconds = secondsSince(t);
    a.projectSweep = runSweep(project.grid, model.point, control);

    const std::optional<double> fd = designFrequency(project, a.check);
    const int n =
        planar ? std::min(options.figureGrid, options.planarFigureGrid) : options.figureGrid;
    t = std::chrono::steady_clock::now();
    const SweepGrid net{
        linspace(project.grid.amplitudes.front(), project.grid.amplitudes.back(), n),
        linspace(project.grid.frequencies.front(), project.grid.frequencies.back(), n)};
    a.netSurface = figureSweep(model, net, control, a.figureRuns);
    a.mapSurface = figureSweep(model, mapGrid(project, a.codes, fd, n), control, a.figureRuns);
    a.figureSweepSeconds = secondsSince(t);

    a.overlay.critFrequencies = a.mapSurface.frequencies;
    a.overlay.critAmplitude =
        criticalCurve(model, project.critical, a.overlay.critFrequencies, a.critRuns);
    a.overlay.designFrequency = fd;
    for (const CodeVerdict& v : a.check.codes)
        a.overlay.codes.push_back(
            {shortCodeName(v.code), v.ratio, v.frequencyHz, codeColour(v.code)});

    if (fd) {
        a.slice.frequency = *fd;
        double aCrit = 0;
        for (const CodeVerdict& v : a.check.codes)
            if (v.aCrit && std::abs(v.frequencyHz - *fd) < 1e-12)
                aCrit = *v.aCrit, a.slice.aCrit = v.aCrit;
        const double hi = std::max(project.grid.amplitudes.back(), 1.25 * aCrit);
        // From one step above 0: an amplitude of 0 is no excitation at all.
        const int steps = static_cast<int>(std::ceil(hi / options.sliceStep));
        const SweepGrid g{linspace(hi / steps, hi, steps), {*fd}};
        const SweepResult r = runSweep(g, model.point, control);
        a.figureRuns += static_cast<long>(r.completed);
        const SurfaceData s = surfaceFromSweep(r, model.tauRef);
        a.slice.amplitudes = s.amplitudes;
        a.slice.gamma = s.gamma;
    }
    if (project.record) {
        RecordAnalysisInput in{c, *project.record, project.critical, a.codes, true, false};
        try {
            a.record = analyseRecord(in, control);
        } catch (const RecordError& e) {
            throw ProjectError("excitation.record.file = '" + project.record->file +
                               "': " + e.what());
        } catch (const std::invalid_argument& e) {
            throw ProjectError(e.what());
        }
    }
    a.floors = computeReportFloors(project, control);
    // The paper's RK4 solver is of the 1-DOF model only.
    if (options.crossCheck && c.solver == SolverKind::Exact && !planar)
        a.crossCheck = crossCheck(project, a.projectSweep, options.crossCheckSteps);
    a.totalSeconds = secondsSince(t0);
    return a;
}

} // namespace kinstab::ui::report
