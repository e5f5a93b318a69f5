// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sweep/Sweep.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <mutex>
#include <thread>

namespace kinstab {

SweepResult runSweep(const SweepGrid& grid, const PointFunction& point, SweepControl* control,
                     int threads) {
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    SweepResult r;
    r.grid = grid;
    const std::size_t total = grid.size();
    r.points.assign(total, PointResult{Outcome::Failed, std::numeric_limits<double>::quiet_NaN()});
    r.done.assign(total, 0);
    const std::size_t nf = grid.frequencies.size();

    std::atomic<std::size_t> next{0};
    std::atomic<std::size_t> completed{0};
    auto worker = [&] {
        while (true) {
            if (control && control->isCancelled()) return;
            const std::size_t k = next.fetch_add(1, std::memory_order_relaxed);
            if (k >= total) return;
            r.points[k] = point(grid.amplitudes[k / nf], grid.frequencies[k % nf]);
            r.done[k] = 1;
            const std::size_t n = completed.fetch_add(1, std::memory_order_acq_rel) + 1;
            if (control && control->onPointDone) control->onPointDone(k);
            if (control && control->onProgress) control->onProgress(n, total);
        }
    };
    int n =
        threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    n = static_cast<int>(
        std::min<std::size_t>(static_cast<std::size_t>(n), std::max<std::size_t>(total, 1)));
    std::vector<std::thread> pool;
    for (int i = 1; i < n; ++i)
        pool.emplace_back(worker);
    worker();
    for (auto& t : pool)
        t.join();

    r.completed = completed.load();
    r.cancelled = r.completed < total;
    r.wallTimeSeconds = std::chrono::duration<double>(Clock::now() - start).count();
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
