#pragma once
// The issue-2 speed target, measured (SPEC §11: speed claims come from benchmarks): the same
// surface swept with the exact solver and with the paper's RK4 at H = T/16, in one process,
// timed over repeated runs that alternate between the two. Also counts the grid points where the
// two disagree on the outcome, so that a speed-up can never hide a change of answer.

#include "core/numerics/Timing.h"
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
};

// The 257 x 257 moderate surface of the speed target: A = 0.5..1.5 g by 1/256,
// f = 0.25..2.25 Hz by 1/128.
SweepGrid benchmarkGrid();

// c.solver is ignored: both solvers run on c (paper at c.paperStepsPerPeriod).
SurfaceBenchmark benchmarkSurface(const Slab1DCase& c, const SweepGrid& grid, int repeats,
                                  int threads);

} // namespace kinstab
