// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Wall-clock timing of repeated runs, the way DiffEqDevTools times work-precision points
// (docs/theory.md §6.7): one warm-up run, then n timed runs; report the minimum (least disturbed
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

struct RunTimes {
    std::vector<double> wall, cpu;

    template <class F> void add(F&& f) {
        using Clock = std::chrono::steady_clock;
        const std::clock_t c0 = std::clock();
        const auto t0 = Clock::now();
        f();
        wall.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
        cpu.push_back(static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC);
    }
    TimingStats stats() const {
        TimingStats s;
        s.runs = static_cast<int>(wall.size());
        s.minSeconds = wall.empty() ? 0.0 : *std::min_element(wall.begin(), wall.end());
        s.medianSeconds = medianOf(wall);
        s.medianCpuSeconds = medianOf(cpu);
        return s;
    }
};

// f() is run 1 + repeats times; the first run is a warm-up and is not counted.
template <class F> TimingStats timeRuns(F&& f, int repeats) {
    f();
    RunTimes t;
    for (int i = 0; i < std::max(repeats, 1); ++i)
        t.add(f);
    return t.stats();
}

// Two jobs timed against each other: after a warm-up of each, the runs alternate (f g, g f,
// f g, ...), so that load from the neighbours, which drifts, falls on both alike. The ratio
// is the median of the per-repeat ratios f/g, not a ratio of medians taken at different times.
struct PairedTiming {
    TimingStats first, second;
    double ratioWall = 0, ratioCpu = 0; // first / second, medians of the per-repeat ratios
};

template <class F, class G> PairedTiming timePaired(F&& f, G&& g, int repeats) {
    f();
    g();
    RunTimes a, b;
    std::vector<double> wall, cpu;
    for (int i = 0; i < std::max(repeats, 1); ++i) {
        if (i % 2 == 0) {
            a.add(f);
            b.add(g);
        } else {
            b.add(g);
            a.add(f);
        }
        wall.push_back(a.wall.back() / b.wall.back());
        cpu.push_back(a.cpu.back() / b.cpu.back());
    }
    return {a.stats(), b.stats(), medianOf(wall), medianOf(cpu)};
}

} // namespace kinstab
