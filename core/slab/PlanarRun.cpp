// SPDX-License-Identifier: GPL-3.0-or-later
// The planar run's time line: windows, the time events (onset, lift-off) and the result.
#include "core/slab/PlanarRun.h"

#include "core/numerics/VectorState.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kinstab {
namespace planar {

WallEvents wallEvents(const PlanarParams& p) {
    const auto wall = [](StateKind kind, int component, double sign, double edge) {
        return StateEvent{kind, Direction::Rising, component, sign, edge, 0.0};
    };
    return {wall(StateKind::CollapseAcross, 0, 1.0, p.limit),
            wall(StateKind::CollapseAcross, 0, -1.0, p.limit),
            wall(StateKind::CollapseAlong, 1, 1.0, p.theta),
            wall(StateKind::CollapseAlong, 1, -1.0, p.theta)};
}

PlanarRun::PlanarRun(const SlabModel2D& m, const PlanarOptions& o, PlanarRecorder* recorder)
    : m_(m), o_(o), recorder_(recorder), mu_(m.params().mu), walls_(wallEvents(m.params())),
      radauTol_(o.relTol) {}

PlanarResult PlanarRun::run() {
    const PlanarParams& p = m_.params();
    const double end = p.duration.value_or(std::numeric_limits<double>::infinity());
    if (!p.duration && !m_.quietAfter(std::numeric_limits<double>::max())) {
        fail("the excitation never decays below mu n: set a duration (tau_out)");
        return r_;
    }
    startLength_ = m_.horizontalTimeScale() / kSlavedStartDivisions;
    slavedSpeed_ = std::clamp(kSlavedSpeed * std::cbrt(o_.relTol / kSlavedSpeedRtol),
                              kSlavedSpeedMin, kSlavedSpeedMax);
    stiffSpeed_ = kStiffSpeed * mu_ * m_.horizontalTimeScale(); // see isStiff
    if (startsLifted()) return r_;
    double w0 = 0.0;
    while (true) {
        if (!slipping_ && m_.quietAfter(w0)) {
            t_ = std::max(t_, w0);
            event(EventKind::Stable);
            finish(Outcome::Stable);
            return r_;
        }
        if (w0 >= end) {
            event(EventKind::DurationCap);
            finish(Outcome::Stable);
            return r_;
        }
        double w1 = std::min(m_.segmentEnd(w0), end);
        if (!(w1 > w0)) w1 = std::nextafter(w0, end);
        if (window(w0, w1) == Step::Done) return r_;
        w0 = w1;
    }
}

// n <= 0 at the start: the slab never rests on its support.
bool PlanarRun::startsLifted() {
    if (m_.normal(0.0) > 0.0) return false;
    r_.tauLiftOff = 0.0;
    r_.slab.tauC = 0.0;
    event(EventKind::LiftOff);
    finish(Outcome::LiftOff);
    return true;
}

// One window of the time line: find lift-off in it, then alternate stuck and sliding stretches.
// The onset roots (|a_h| = mu n) matter only while the slab is stuck or slaved (whose quadrature
// needs a fixed sign of |a_h| - mu n): they are scanned for then, once per window; a slip
// integrated by the explicit method crosses them as any other time.
PlanarRun::Step PlanarRun::window(double w0, double w1) {
    m_.enterWindow(w0, w1);
    double wEnd = w1;
    const bool lifts = scanLiftOff(w0, w1, wEnd);
    winStart_ = w0;
    winEnd_ = wEnd;
    cutsKnown_ = false;
    while (slipping_ || t_ < wEnd) {
        if (!slipping_) {
            const double onset = nextOnset(std::max(t_, w0));
            if (!(onset < wEnd)) break;
            if (startSlip(onset) == Step::Done) return Step::Done;
        }
        if (slipTo(wEnd) == Step::Done) return Step::Done;
        if (slipping_ && t_ >= wEnd) break;
    }
    if (!slipping_) t_ = std::max(t_, wEnd);
    if (!lifts) return Step::Continue;
    // n reached 0: the slab leaves its support. Reported, never integrated through.
    t_ = wEnd;
    r_.tauLiftOff = wEnd;
    r_.slab.tauC = wEnd;
    event(EventKind::LiftOff);
    return finish(Outcome::LiftOff);
}

// The lift-off event's first root in [w0, w1] (when n may reach 0 there) ends the window.
bool PlanarRun::scanLiftOff(double w0, double w1, double& wEnd) {
    if (!m_.mayLiftOn(w0, w1)) return false;
    roots_.clear();
    scanTimeEvent(kLiftOffEvent, w0, w1, roots_);
    if (roots_.empty()) return false;
    wEnd = roots_.front();
    return true;
}

// Slip onset: the slab lags the walls and starts along -a_h.
PlanarRun::Step PlanarRun::startSlip(double onset) {
    t_ = onset;
    slipping_ = true;
    slipPeak_ = 0.0;
    y_[2] = y_[3] = 0.0;
    ++r_.slab.slipIntervals;
    return event(EventKind::SlipOnset) ? Step::Continue : Step::Done;
}

// The roots of a time event's function in (lo, hi], appended to out; with `from`, only those
// of the sub-intervals that end after it.
void PlanarRun::scanTimeEvent(const TimeEvent& e, double lo, double hi, std::vector<double>& out,
                              double from) {
    CrossingScanWork scan;
    levelCrossings([&](double t, double& f, double& df) { (m_.*e.gAndSlope)(t, f, df); }, lo, hi,
                   kTimeEventSub, out, scan, from);
    r_.slab.work.accelEvaluations += scan.evaluations;
    r_.slab.work.rootIterations += scan.iterations;
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
    if (m_.quietOn(from, winEnd_)) return winEnd_;
    scanCuts(from, false);
    for (std::size_t i = 0; i + 1 < cuts_.size(); ++i) {
        const double lo = std::max(cuts_[i], from), hi = cuts_[i + 1];
        if (hi > lo && m_.onsetMargin(0.5 * (lo + hi)) > 0.0) return lo;
    }
    return winEnd_;
}

// The first onset root after tau in the window (winEnd_ when none): where a slaved stretch ends.
double PlanarRun::nextCut(double tau) {
    if (!cutsKnown_) scanCuts(tau, m_.quietOn(tau, winEnd_));
    const auto it = std::upper_bound(cuts_.begin(), cuts_.end(), tau);
    return it == cuts_.end() ? winEnd_ : *it;
}

void PlanarRun::moveTo(double tau, const Vec4& y) {
    t_ = tau;
    y_ = y;
    r_.slab.maxAbsDelta = std::max(r_.slab.maxAbsDelta, std::abs(y[0]));
    r_.maxAbsDeltaY = std::max(r_.maxAbsDeltaY, std::abs(y[1]));
    slipPeak_ = std::max(slipPeak_, norm2(y[2], y[3]));
    if (recorder_) recorder_->onStep({tau, y[0], y[1], y[2], y[3], slipping_});
}

bool PlanarRun::event(EventKind kind) {
    ++r_.slab.work.events;
    if (recorder_) recorder_->onEvent({t_, kind, y_[0], y_[1], y_[2], y_[3]});
    if (r_.slab.work.events > o_.maxEvents) {
        fail("more than " + std::to_string(o_.maxEvents) + " events (chattering guard)");
        return false;
    }
    return true;
}

PlanarRun::Step PlanarRun::finish(Outcome o) {
    r_.slab.outcome = o;
    r_.slab.tauEnd = t_;
    r_.slab.residualDelta = y_[0];
    r_.residualDeltaY = y_[1];
    return Step::Done;
}

PlanarRun::Step PlanarRun::fail(const std::string& why) {
    r_.slab.failure = why;
    return finish(Outcome::Failed);
}

} // namespace planar

PlanarResult solvePlanar(const SlabModel2D& model, const PlanarOptions& options,
                         PlanarRecorder* recorder) {
    clearUpperVectorState(); // see VectorState.h: a host process may leave AVX state dirty
    const std::string e = validatePlanarParams(model.params());
    if (!e.empty()) {
        PlanarResult r;
        r.slab.outcome = Outcome::Failed;
        r.slab.failure = e;
        return r;
    }
    return planar::PlanarRun(model, options, recorder).run();
}

} // namespace kinstab
