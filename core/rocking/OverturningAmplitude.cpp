// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/rocking/OverturningAmplitude.h"

#include "core/rocking/RockingSolver.h"

#include <stdexcept>
#include <string>

namespace kinstab {

std::optional<double> OverturningIntervals::critical() const {
    if (intervals.empty()) return std::nullopt;
    return intervals.front().first;
}

namespace {

struct Prober {
    const RockingModel& model;
    const MotionFamily& family;
    long runs = 0;
    bool overturns(double amplitude) {
        ++runs;
        const std::unique_ptr<BaseMotion> motion = family(amplitude);
        RockingRunOptions o;
        o.stopAtOverturnDecision = true;
        const RockingOutcome out = simulateRocking(model, *motion, o).outcome;
        return out == RockingOutcome::Overturns || out == RockingOutcome::LeavesBase;
    }
    // The change between lo (outcome lowOverturns) and hi (the other), narrowed to the
    // tolerance (relative): the last amplitude with lo's outcome and the first with hi's.
    std::pair<double, double> bisect(double lo, double hi, bool lowOverturns,
                                     const OverturningSearch& s) {
        for (int i = 0; i < s.maxBisections && hi - lo > s.tolerance * hi; ++i) {
            const double mid = 0.5 * (lo + hi);
            (overturns(mid) == lowOverturns ? lo : hi) = mid;
        }
        return {lo, hi};
    }
};

void checkSearch(const OverturningSearch& s) {
    if (!(s.maxAmplitude > 0.0) || s.scanPoints < 1 || s.scanPoints > 100000 ||
        !(s.tolerance > 0.0 && s.tolerance < 0.5) || s.maxBisections < 1 || s.maxBisections > 200)
        throw std::invalid_argument("overturning search: max amplitude " +
                                    std::to_string(s.maxAmplitude) + ", " +
                                    std::to_string(s.scanPoints) + " scan points: out of range");
}

} // namespace

// Scan, then bisect every change between neighbouring amplitudes: an interval begins where the
// outcome turns to overturning (its first overturning amplitude, to the tolerance) and ends
// where it turns back (its last one). Zero amplitude never overturns (a block at rest stays).
OverturningIntervals overturningIntervals(const RockingModel& model, const MotionFamily& family,
                                          const OverturningSearch& search,
                                          const SweepControl* control) {
    checkSearch(search);
    Prober probe{model, family};
    OverturningIntervals out;
    double previous = 0.0;
    bool previousOverturns = false;
    for (int k = 1; k <= search.scanPoints; ++k) {
        if (control && control->isCancelled()) break;
        const double a = search.maxAmplitude * k / search.scanPoints;
        const bool now = probe.overturns(a);
        if (now && !previousOverturns) {
            out.intervals.push_back(
                {probe.bisect(previous, a, false, search).second, search.maxAmplitude});
        } else if (!now && previousOverturns) {
            out.intervals.back().second = probe.bisect(previous, a, true, search).first;
        }
        previous = a;
        previousOverturns = now;
        if (control && control->onProgress)
            control->onProgress(static_cast<std::size_t>(k),
                                static_cast<std::size_t>(search.scanPoints));
    }
    out.runs = probe.runs;
    return out;
}

} // namespace kinstab
