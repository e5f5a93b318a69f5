// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sweep/CriticalAmplitude.h"

#include "core/base/InternalError.h"
#include "core/base/TextInput.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

namespace kinstab {

double smallestTolerance(double maxAmplitude) {
    return 4.0 * std::numeric_limits<double>::epsilon() * std::abs(maxAmplitude);
}

InputProblem checkCriticalSearch(const CriticalSearch& s) {
    for (const auto& [in, x] : {std::pair{&kSearchFromInput, s.from},
                                {&kMaxAmplitudeInput, s.to},
                                {&kScanStepInput, s.scanStep},
                                {&kToleranceInput, s.tolerance}})
        if (InputProblem p = checkInput(*in, x); !p.empty()) return p;
    if (!(s.to > s.from))
        return {"max_amplitude", s.to, "g",
                "must exceed the scan's start, " + formatDouble(s.from) + " g"};
    if (s.scanStep > s.to - s.from)
        return {"scan_step", s.scanStep, "g",
                "must be at most the searched range, " + formatDouble(s.to - s.from) + " g"};
    const double finestStep = (s.to - s.from) / static_cast<double>(kMaxScanPoints);
    if (s.scanStep < finestStep)
        return {"scan_step", s.scanStep, "g",
                "at most " + std::to_string(kMaxScanPoints) +
                    " scan points; the smallest step up to " + formatDouble(s.to) + " g is " +
                    formatDouble(finestStep) + " g"};
    if (s.tolerance > s.scanStep)
        return {"tolerance", s.tolerance, "g",
                "must be at most the scan step, " + formatDouble(s.scanStep) + " g"};
    if (s.tolerance < smallestTolerance(s.to))
        return {"tolerance", s.tolerance, "g",
                "below what double precision resolves at " + formatDouble(s.to) +
                    " g (the smallest is " + formatDouble(smallestTolerance(s.to)) + " g)"};
    return {};
}

CriticalResult criticalAmplitude(const PointFunction& point, double frequencyHz, double scanFrom,
                                 const CriticalSearch& search) {
    CriticalResult r;
    auto collapses = [&](double a) {
        ++r.runs;
        return point(a, frequencyHz).outcome == Outcome::Collapsed;
    };
    // Below scanFrom the slab never slips, so the scan starts there.
    double lo = std::max(search.from, scanFrom);
    if (collapses(lo)) {
        r.amplitude = lo;
        return r;
    }
    const double base = lo;
    double hi = lo;
    bool found = false;
    // A limit on the scan grid within rounding ((0.65 - 0.6) / 0.01 = 5.000000000000004) is its
    // last point, not one more step that the clamp below would only repeat.
    const double span = std::ceil((search.to - base) / search.scanStep - 1e-9);
    if (!(span <= static_cast<double>(kMaxScanPoints)))
        throw InternalError("critical amplitude scan: " + std::to_string(span) + " points from " +
                            std::to_string(base) + " g to " + std::to_string(search.to) +
                            " g exceed " + std::to_string(kMaxScanPoints));
    const long steps = static_cast<long>(span);
    for (long k = 1; k <= steps; ++k) {
        hi = std::min(search.to, base + static_cast<double>(k) * search.scanStep);
        if (collapses(hi)) {
            found = true;
            break;
        }
        lo = hi;
    }
    if (!found) return r;
    // Below the bracket's resolution the midpoint is one of its ends and halving stops there:
    // a tolerance finer than double precision ends at adjacent doubles, not in a loop.
    const double tolerance = std::max(search.tolerance, smallestTolerance(hi));
    for (int halvings = 0; hi - lo > tolerance && halvings < kMaxHalvings; ++halvings) {
        const double mid = 0.5 * (lo + hi);
        if (!(mid > lo && mid < hi)) break;
        if (collapses(mid))
            hi = mid;
        else
            lo = mid;
    }
    r.amplitude = hi;
    return r;
}

} // namespace kinstab
