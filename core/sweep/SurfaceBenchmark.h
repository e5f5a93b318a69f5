// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The issue-2 speed target, measured (docs/theory.md §6.6: speed claims come from benchmarks): the
// same surface swept with the exact solver and with the paper's RK4 at H = T/16, in one process,
// timed over repeated runs that alternate between the two. Also counts the grid points where the
// two disagree on the outcome, so that a speed-up can never hide a change of answer.

#include "core/numerics/Timing.h"
#include "core/slab/PlanarCase.h"
#include "core/slab/Slab1DCase.h"
#include "core/sweep/Grid.h"

namespace kinstab {

struct SurfaceBenchmark {
    SweepGrid grid;
    int threads = 0;
    TimingStats exact, paper;
    double ratioMedian = 0; // exact / paper: median of the per-repeat wall-time ratios
    double ratioCpu = 0;    // the same for CPU time
    std::size_t outcomeDisagreements = 0;
    std::size_t exactCollapsed = 0;
    // The exact solver's work over the surface (one pass, outside the timings): its events and
    // its closed-form evaluations, every root solve's included (issue 34).
    long exactEvents = 0, exactEvaluations = 0;
};

// The 257 x 257 moderate surface of the speed target: A = 0.5..1.5 g by 1/256,
// f = 0.25..2.25 Hz by 1/128.
SweepGrid benchmarkGrid();

// c.solver is ignored: both solvers run on c (paper at c.paperStepsPerPeriod).
SurfaceBenchmark benchmarkSurface(const Slab1DCase& c, const SweepGrid& grid, int repeats,
                                  int threads);

// Whether core/numerics/VectorState.h still pays in this process: the exact surface with the
// vzeroupper at each solver start against the same surface without it, runs alternating.
struct VectorStateBenchmark {
    SweepGrid grid;
    int threads = 0;
    TimingStats cleared, uncleared;
    double ratioMedian = 0; // uncleared / cleared: median of the per-repeat wall-time ratios
    double ratioCpu = 0;
};
VectorStateBenchmark benchmarkVectorState(const Slab1DCase& c, const SweepGrid& grid, int repeats,
                                          int threads);

// The issue-22 target: the planar surface against the 1-DOF (exact) surface on the same grid,
// runs alternating planar / 1-DOF in one process. Counts the planar collapses and those along
// the walls, so that a speed-up cannot hide a change of answer.
struct PlanarSurfaceBenchmark {
    SweepGrid grid;
    int threads = 0;
    TimingStats planar, oneDof;
    double ratioMedian = 0; // planar / 1-DOF: median of the per-repeat wall-time ratios
    double ratioCpu = 0;
    std::size_t planarCollapsed = 0, planarAlongWalls = 0, planarLiftOff = 0;
    long planarSteps = 0, planarEvaluations = 0; // solver work over the surface (one run)
};

// The 33 x 33 grid over the span of benchmarkGrid(): A 0.5:1.5:1/32, f 0.25:2.25:1/16.
SweepGrid planarBenchmarkGrid();

// oneDof.solver is forced to the exact solver; planar runs as given (its solver options too).
PlanarSurfaceBenchmark benchmarkPlanarSurface(const Slab1DCase& oneDof, const PlanarCase& planar,
                                              const SweepGrid& grid, int repeats, int threads);

} // namespace kinstab
