// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/analysis/CriticalCurve.h"

#include "core/sweep/ParallelFor.h"

#include <atomic>

namespace kinstab {

CriticalCurve criticalCurve(const PointFunction& point, const std::vector<double>& frequencies,
                            double scanFrom, const CriticalSearch& search, SweepControl* control,
                            int threads) {
    const std::size_t n = frequencies.size();
    CriticalCurve c;
    c.frequencies = frequencies;
    c.amplitude.assign(n, std::nullopt);
    c.done.assign(n, 0);
    std::vector<long> runs(n, 0);
    std::atomic<std::size_t> completed{0};
    parallelFor(n, threads, control, [&](std::size_t j) {
        const CriticalResult r = criticalAmplitude(point, frequencies[j], scanFrom, search);
        // A search a cancel cut short may have met the wrapped point's early "no collapse".
        if (control && control->isCancelled()) return;
        c.amplitude[j] = r.amplitude;
        runs[j] = r.runs;
        c.done[j] = 1;
        const std::size_t k = completed.fetch_add(1, std::memory_order_acq_rel) + 1;
        if (control && control->onProgress) control->onProgress(k, n);
    });
    for (long r : runs)
        c.runs += r;
    c.cancelled = (control && control->isCancelled()) || completed.load() < n;
    return c;
}

} // namespace kinstab
