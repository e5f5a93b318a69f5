// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sweep/SurfaceBenchmark.h"

#include "core/numerics/VectorState.h"
#include "core/sweep/Sweep.h"

#include <algorithm>
#include <atomic>
#include <thread>

namespace kinstab {

SweepGrid benchmarkGrid() {
    return {linspaceStep(0.5, 1.5, 1.0 / 256.0), linspaceStep(0.25, 2.25, 1.0 / 128.0)};
}

SweepGrid planarBenchmarkGrid() {
    return {linspaceStep(0.5, 1.5, 1.0 / 32.0), linspaceStep(0.25, 2.25, 1.0 / 16.0)};
}

namespace {
int threadsOrAll(int threads) {
    return threads > 0 ? threads
                       : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
}
} // namespace

SurfaceBenchmark benchmarkSurface(const Slab1DCase& c, const SweepGrid& grid, int repeats,
                                  int threads) {
    SurfaceBenchmark b;
    b.grid = grid;
    b.threads = threadsOrAll(threads);
    Slab1DCase exact = c, paper = c;
    exact.solver = SolverKind::Exact;
    paper.solver = SolverKind::Paper;
    SweepResult exactResult, paperResult;
    const PairedTiming t = timePaired(
        [&] { exactResult = runSweep(grid, slab1DPoint(exact), nullptr, b.threads); },
        [&] { paperResult = runSweep(grid, slab1DPoint(paper), nullptr, b.threads); }, repeats);
    b.exact = t.first;
    b.paper = t.second;
    b.ratioMedian = t.ratioWall;
    b.ratioCpu = t.ratioCpu;
    for (std::size_t k = 0; k < exactResult.points.size(); ++k) {
        if (exactResult.points[k].outcome != paperResult.points[k].outcome)
            ++b.outcomeDisagreements;
        if (exactResult.points[k].outcome == Outcome::Collapsed) ++b.exactCollapsed;
    }
    // The solver's work, counted once outside the timed runs.
    std::atomic<long> events = 0, evaluations = 0;
    runSweep(
        grid,
        [&](double a, double f) {
            const SlabResult r = runSlab1D(exact, a, f, RunOptions{});
            events += r.work.events;
            evaluations += r.work.accelEvaluations;
            return PointResult{r.outcome, r.tauC, ExitSide::None};
        },
        nullptr, b.threads);
    b.exactEvents = events;
    b.exactEvaluations = evaluations;
    return b;
}

VectorStateBenchmark benchmarkVectorState(const Slab1DCase& c, const SweepGrid& grid, int repeats,
                                          int threads) {
    VectorStateBenchmark b;
    b.grid = grid;
    b.threads = threadsOrAll(threads);
    Slab1DCase exact = c;
    exact.solver = SolverKind::Exact;
    std::atomic<bool>& clearing = upperVectorStateClearing();
    const PairedTiming t = timePaired(
        [&] {
            clearing = false;
            runSweep(grid, slab1DPoint(exact), nullptr, b.threads);
        },
        [&] {
            clearing = true;
            runSweep(grid, slab1DPoint(exact), nullptr, b.threads);
        },
        repeats);
    clearing = true;
    b.uncleared = t.first;
    b.cleared = t.second;
    b.ratioMedian = t.ratioWall;
    b.ratioCpu = t.ratioCpu;
    return b;
}

PlanarSurfaceBenchmark benchmarkPlanarSurface(const Slab1DCase& oneDof, const PlanarCase& planar,
                                              const SweepGrid& grid, int repeats, int threads) {
    PlanarSurfaceBenchmark b;
    b.grid = grid;
    b.threads = threadsOrAll(threads);
    Slab1DCase exact = oneDof;
    exact.solver = SolverKind::Exact;
    SweepResult planarResult;
    const PairedTiming t =
        timePaired([&] { planarResult = runSweep(grid, planarPoint(planar), nullptr, b.threads); },
                   [&] { runSweep(grid, slab1DPoint(exact), nullptr, b.threads); }, repeats);
    b.planar = t.first;
    b.oneDof = t.second;
    b.ratioMedian = t.ratioWall;
    b.ratioCpu = t.ratioCpu;
    for (const PointResult& p : planarResult.points) {
        if (p.outcome == Outcome::Collapsed) ++b.planarCollapsed;
        if (p.outcome == Outcome::LiftOff) ++b.planarLiftOff;
        if (p.exitSide == ExitSide::Along) ++b.planarAlongWalls;
    }
    // The solver's work, counted once outside the timed runs.
    std::atomic<long> steps = 0, evaluations = 0;
    runSweep(
        grid,
        [&](double a, double f) {
            const PlanarResult r = runPlanar(planar, a, f);
            steps += r.slab.work.steps;
            evaluations += r.slab.work.accelEvaluations;
            return PointResult{r.slab.outcome, r.slab.tauC, r.exitSide};
        },
        nullptr, b.threads);
    b.planarSteps = steps;
    b.planarEvaluations = evaluations;
    return b;
}

} // namespace kinstab
