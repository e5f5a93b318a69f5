#pragma once
// Wall-clock timing of repeated runs, the way DiffEqDevTools times work-precision points
// (NUMERICS.md §3.1): one warm-up run, then n timed runs; report the minimum (least disturbed
// by other load on the machine) and the median. Process CPU time is kept beside it because
// wall time on a shared machine measures the neighbours too.

#include <algorithm>
#include <chrono>
#include <ctime>
#include <vector>

namespace kinstab {

struct TimingStats {
    double minSeconds = 0;
    double medianSeconds = 0;
    double medianCpuSeconds = 0; // process CPU time (all threads) per run, median
    int runs = 0;
};

inline double medianOf(std::vector<double> v) {
    if (v.empty()) return 0.0;
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

// f() is run 1 + repeats times; the first run is a warm-up and is not counted.
template <class F> TimingStats timeRuns(F&& f, int repeats) {
    using Clock = std::chrono::steady_clock;
    f();
    std::vector<double> wall, cpu;
    for (int i = 0; i < std::max(repeats, 1); ++i) {
        const std::clock_t c0 = std::clock();
        const auto t0 = Clock::now();
        f();
        wall.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
        cpu.push_back(static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
    }
    TimingStats s;
    s.runs = static_cast<int>(wall.size());
    s.minSeconds = *std::min_element(wall.begin(), wall.end());
    s.medianSeconds = medianOf(wall);
    s.medianCpuSeconds = medianOf(cpu);
    return s;
}

} // namespace kinstab
