// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sweep/Sweep.h"

#include "core/base/Stopwatch.h"
#include "core/sweep/ParallelFor.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>

namespace kinstab {

SweepResult runSweep(const SweepGrid& grid, const PointFunction& point, SweepControl* control,
                     int threads) {
    const auto start = SteadyClock::now();
    SweepResult r;
    r.grid = grid;
    const std::size_t total = grid.size();
    r.points.assign(total, PointResult{Outcome::Failed, std::numeric_limits<double>::quiet_NaN()});
    r.done.assign(total, 0);
    const std::size_t nf = grid.frequencies.size();

    std::atomic<std::size_t> completed{0};
    parallelFor(total, threads, control, [&](std::size_t k) {
        r.points[k] = point(grid.amplitudes[k / nf], grid.frequencies[k % nf]);
        r.done[k] = 1;
        const std::size_t n = completed.fetch_add(1, std::memory_order_acq_rel) + 1;
        if (control && control->onPointDone) control->onPointDone(k, r.points[k]);
        if (control && control->onProgress) control->onProgress(n, total);
    });
    r.completed = completed.load();
    r.cancelled = r.completed < total;
    r.wallTimeSeconds = secondsSince(start);
    return r;
}

PointFunction slab1DPoint(const Slab1DCase& c) {
    return [c](double amplitude, double frequency) {
        const SlabResult s = runSlab1D(c, amplitude, frequency);
        return PointResult{s.outcome, s.tauC};
    };
}

std::vector<double> collapseFactors(const SweepResult& r, double tauRef) {
    std::vector<double> g(r.points.size(), 0.0);
    for (std::size_t k = 0; k < g.size(); ++k)
        if (r.points[k].outcome == Outcome::Collapsed) g[k] = tauRef / r.points[k].tauC;
    return g;
}

} // namespace kinstab
