// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/rocking/BaseMotion.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kinstab {

namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}

// On a monotone piece the excess sign a_h - level (1 + a_v) changes sign at most once (a_v
// constant or, in a record's sample interval, linear with a_h: the excess is linear), so the
// ends decide and bisection finds the time to the last bit.
double BaseMotion::firstExceedance(int sign, double level, double t0, double t1) const {
    auto excess = [&](double t) { return sign * horizontal(t) - level * (1.0 + vertical(t)); };
    if (excess(t0) > 0.0) return t0;
    if (!(excess(t1) > 0.0)) return kNaN;
    double lo = t0, hi = t1;
    for (int i = 0; i < 200 && hi - lo > 2.0 * std::numeric_limits<double>::epsilon() * hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        (excess(mid) > 0.0 ? hi : lo) = mid;
    }
    return hi;
}

ExcitationMotion::ExcitationMotion(std::shared_ptr<const Excitation1D> horizontal, double tstar,
                                   double endTime, std::shared_ptr<const Excitation1D> vertical)
    : horizontal_(std::move(horizontal)), vertical_(std::move(vertical)), tstar_(tstar),
      end_(endTime) {}

double ExcitationMotion::horizontal(double t) const {
    return t > end_ ? 0.0 : horizontal_->accel(t / tstar_);
}

double ExcitationMotion::vertical(double t) const {
    return !vertical_ || t > end_ ? 0.0 : vertical_->accel(t / tstar_);
}

// The excitation's segments: a recorded motion's sample intervals (a linear in each), an
// enveloped sine's half-periods (one hump each; firstExceedance below uses its exact crossings).
double ExcitationMotion::pieceEnd(double t) const {
    if (t >= end_) return std::numeric_limits<double>::infinity();
    const double tau = t / tstar_;
    double next = horizontal_->segmentEnd(tau);
    if (vertical_) next = std::min(next, vertical_->segmentEnd(tau));
    double end = next * tstar_;
    // A rounding of t / tstar at a knot may give back the knot itself: take the next one.
    if (!(end > t * (1.0 + 4.0 * std::numeric_limits<double>::epsilon()))) {
        next = horizontal_->segmentEnd(next * (1.0 + 1e-12));
        end = next * tstar_;
    }
    return std::min(end, end_);
}

// Without a vertical motion the excitation's own crossings are exact on its segment (a hump
// of an enveloped sine may cross a level twice); with one (a record's, linear in the interval)
// the excess is linear and the default's ends decide.
double ExcitationMotion::firstExceedance(int sign, double level, double t0, double t1) const {
    if (vertical_) return BaseMotion::firstExceedance(sign, level, t0, t1);
    if (sign * horizontal(t0) > level) return t0;
    const Crossings c = horizontal_->crossings(sign * level, t0 / tstar_, t1 / tstar_);
    for (int i = 0; i < c.n; ++i) {
        const double t = c.t[static_cast<std::size_t>(i)] * tstar_;
        // The first crossing upwards; a crossing's time may round to either side of it.
        const double after = std::min(t1, t * (1.0 + 1e-15) + 1e-300);
        if (sign * horizontal(after) > level || sign * horizontal(t) > level) return t;
    }
    return sign * horizontal(t1) > level ? t1 : kNaN;
}

} // namespace kinstab
