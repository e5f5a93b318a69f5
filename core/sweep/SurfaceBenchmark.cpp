#include "core/sweep/SurfaceBenchmark.h"

#include "core/sweep/Sweep.h"

#include <thread>

namespace kinstab {

SweepGrid benchmarkGrid() {
    return {linspaceStep(0.5, 1.5, 1.0 / 256.0), linspaceStep(0.25, 2.25, 1.0 / 128.0)};
}

SurfaceBenchmark benchmarkSurface(const Slab1DCase& c, const SweepGrid& grid, int repeats,
                                  int threads) {
    SurfaceBenchmark b;
    b.grid = grid;
    b.threads =
        threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
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
    return b;
}

} // namespace kinstab
