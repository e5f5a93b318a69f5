// SPDX-License-Identifier: GPL-3.0-or-later
// The planar run's time events (core/slab/PlanarEvents.h): lift-off and slip onset, functions of
// tau alone, scanned on a window of the time line, and the onset roots that cut a window into
// pieces of one sign of |a_h| - mu n.
#include "core/slab/PlanarRun.h"

#include <algorithm>
#include <cmath>

namespace kinstab::planar {

// The lift-off event's first root in [w0, w1] (when n may reach 0 there) ends the window.
bool PlanarRun::scanLiftOff(double w0, double w1, double& wEnd) {
    if (!m_.mayLiftOn(w0, w1)) return false;
    roots_.clear();
    scanTimeEvent(kLiftOffEvent, w0, w1, roots_);
    if (roots_.empty()) return false;
    wEnd = roots_.front();
    return true;
}

// The roots of a time event's function in (lo, hi], appended to out; with `from`, only those
// of the sub-intervals that end after it.
void PlanarRun::scanTimeEvent(const TimeEvent& e, double lo, double hi, std::vector<double>& out,
                              double from) {
    CrossingScanWork scan;
    const int sub = &e == &kOnsetEvent ? onsetSubIntervals(lo, hi) : kTimeEventSub;
    levelCrossings(
        [&](double t, double& f, double& df) {
            (m_.*e.gAndSlope)(t, f, df);
            // At the window's end a record's next sample interval starts: whether g turns inside
            // the window is told by the slope from inside (the next piece's had hidden a hump of
            // the last sub-interval whose ends were both below 0).
            double inside = 0.0;
            if (!(t == hi && hi > lo)) return;
            (m_.*e.gAndSlope)(std::nextafter(hi, lo), inside, df);
            ++scan.evaluations;
        },
        lo, hi, sub, out, scan, from);
    r_.slab.work.accelEvaluations += scan.evaluations;
    r_.slab.work.rootIterations += scan.iterations;
}

// kTimeEventSub sub-intervals on a window as long as the horizontal time scale, fewer on a shorter
// one (none longer than the time scale over kTimeEventSub).
int PlanarRun::onsetSubIntervals(double lo, double hi) const {
    const double n = std::ceil(kTimeEventSub * (hi - lo) / timeScale_);
    if (!(n < kTimeEventSub)) return kTimeEventSub; // NaN too
    return std::max(1, static_cast<int>(n));
}

// The window's onset roots after `from`, scanned on first use: cuts_ = {start, roots..., end}.
// Only where the slab sticks or is slaved from `from` on is the rest of the window scanned (the
// run's time never goes back); the sub-intervals stay the window's, so the roots are the bits a
// scan of the whole window gives. `quiet`: nothing can start after `from` (no roots there).
void PlanarRun::scanCuts(double from, bool quiet) {
    if (cutsKnown_) return;
    cutsKnown_ = true;
    cuts_.clear();
    cuts_.push_back(winStart_);
    if (!quiet) scanTimeEvent(kOnsetEvent, winStart_, winEnd_, cuts_, from);
    cuts_.push_back(winEnd_);
}

// The first time at or after `from` in the window where the slab slips (|a_h| > mu n on the
// piece that follows); winEnd_ when there is none.
double PlanarRun::nextOnset(double from) {
    if (quietOn(from, winEnd_)) return winEnd_;
    scanCuts(from, false);
    for (std::size_t i = 0; i + 1 < cuts_.size(); ++i) {
        const double lo = std::max(cuts_[i], from), hi = cuts_[i + 1];
        if (hi > lo && m_.onsetMargin(0.5 * (lo + hi)) > 0.0) return lo;
    }
    return winEnd_;
}

// The first onset root after tau in the window (winEnd_ when none): where a slaved stretch ends.
double PlanarRun::nextCut(double tau) {
    if (!cutsKnown_) scanCuts(tau, quietOn(tau, winEnd_));
    const auto it = std::upper_bound(cuts_.begin(), cuts_.end(), tau);
    return it == cuts_.end() ? winEnd_ : *it;
}

// The model's bounds answered once per horizontal time scale T where they can be: with a record
// cutting the time line at every sample they had been asked per window (a twelfth of a run).
// The answers are the model's: both bounds hold on any part of the span they were asked for.
// Nothing can start in [lo, hi]: first from a bound over the span [lo, lo + T] that covers it.
bool PlanarRun::quietOn(double lo, double hi) {
    if (lo >= quietSpan_.lo && hi <= quietSpan_.hi) return true;
    // A loud window is asked twice: whether it can be passed whole, then for its onsets.
    if (lo == lastLoud_.lo && hi == lastLoud_.hi) return false;
    if (quietOnModel(lo, hi)) return true;
    lastLoud_ = {lo, hi};
    return false;
}

bool PlanarRun::quietOnModel(double lo, double hi) {
    if (lo >= loudSpanEnd_ && hi - lo < timeScale_) {
        const double spanEnd = lo + timeScale_;
        if (m_.quietOn(lo, spanEnd)) {
            quietSpan_ = {lo, spanEnd};
            return true;
        }
        loudSpanEnd_ = spanEnd; // not tried again before its end
    }
    return m_.quietOn(lo, hi);
}

// Nothing can start after tau. The bounds after tau fall as tau grows (|a_h|'s and |a_z|'s), so
// a motion not quiet after tau + T is not quiet after tau either.
bool PlanarRun::quietAfter(double tau) {
    if (tau <= loudUntil_) return false;
    const double ahead = tau + timeScale_;
    if (!m_.quietAfter(ahead)) {
        loudUntil_ = ahead;
        return false;
    }
    return m_.quietAfter(tau);
}

} // namespace kinstab::planar
