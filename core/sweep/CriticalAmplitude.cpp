#include "core/sweep/CriticalAmplitude.h"

#include <algorithm>
#include <cmath>

namespace kinstab {

CriticalResult criticalAmplitude(const PointFunction& point, double frequencyHz, double mu,
                                 const CriticalSearch& search) {
    CriticalResult r;
    auto collapses = [&](double a) {
        ++r.runs;
        return point(a, frequencyHz).outcome == Outcome::Collapsed;
    };
    // Below mu the slab never slips, so the scan starts there.
    double lo = std::max(search.from, mu);
    if (collapses(lo)) {
        r.amplitude = lo;
        return r;
    }
    const double base = lo;
    double hi = lo;
    bool found = false;
    // A limit on the scan grid within rounding ((0.65 - 0.6) / 0.01 = 5.000000000000004) is its
    // last point, not one more step that the clamp below would only repeat.
    const long steps = static_cast<long>(std::ceil((search.to - base) / search.scanStep - 1e-9));
    for (long k = 1; k <= steps; ++k) {
        hi = std::min(search.to, base + static_cast<double>(k) * search.scanStep);
        if (collapses(hi)) {
            found = true;
            break;
        }
        lo = hi;
    }
    if (!found) return r;
    while (hi - lo > search.tolerance) {
        const double mid = 0.5 * (lo + hi);
        if (collapses(mid))
            hi = mid;
        else
            lo = mid;
    }
    r.amplitude = hi;
    return r;
}

} // namespace kinstab
