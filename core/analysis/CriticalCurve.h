// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A_crit(f): the critical amplitude (core/sweep/CriticalAmplitude.h) at each of a list of
// frequencies, searched on core's thread pool. The one loop behind the GUI's A_crit chart, the
// report's overlay and kinstab-cli critical (1-DOF and planar).

#include "core/sweep/CriticalAmplitude.h"
#include "core/sweep/SweepControl.h"

#include <optional>
#include <vector>

namespace kinstab {

struct CriticalCurve {
    std::vector<double> frequencies;
    std::vector<std::optional<double>> amplitude; // per frequency; nullopt: nothing collapses
    std::vector<unsigned char> done; // 1 where the search finished (a cancel leaves holes)
    long runs = 0;                   // slab runs of all searches
    bool cancelled = false;
};

// scanFrom: where every scan starts, below which nothing slips (ModelPoint::scanFrom). control:
// cancel stops handing out frequencies (wrap `point` to return at once after a cancel so a
// running search ends within one run too); onProgress is called once per frequency searched.
// An exception from `point` is rethrown: the one of the lowest frequency index, as a plain loop.
CriticalCurve criticalCurve(const PointFunction& point, const std::vector<double>& frequencies,
                            double scanFrom, const CriticalSearch& search,
                            SweepControl* control = nullptr, int threads = 0);

} // namespace kinstab
