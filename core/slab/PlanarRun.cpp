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
    timeScale_ = m_.horizontalTimeScale();
    startLength_ = timeScale_ / kSlavedStartDivisions;
    slavedSpeed_ = std::clamp(kSlavedSpeed * std::cbrt(o_.relTol / kSlavedSpeedRtol),
                              kSlavedSpeedMin, kSlavedSpeedMax);
    stiffSpeed_ = kStiffSpeed * mu_ * m_.horizontalTimeScale(); // see isStiff
    if (startsLifted()) return r_;
    double w0 = 0.0;
    while (true) {
        if (!slipping_ && quietAfter(w0)) {
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
    // Stuck, no lift-off possible and nothing can start: the window passes as a whole, without
    // entering it (with a record every sample is a window, and entering them was a twentieth of
    // a run with RSN68 UP). The same answer the onset search below gives.
    if (!slipping_ && !m_.mayLiftOn(w0, w1) && quietOn(std::max(t_, w0), w1)) {
        t_ = std::max(t_, w1);
        return Step::Continue;
    }
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

// Slip onset: the slab lags the walls and starts along -a_h.
PlanarRun::Step PlanarRun::startSlip(double onset) {
    t_ = onset;
    slipping_ = true;
    slipPeak_ = 0.0;
    y_[2] = y_[3] = 0.0;
    ++r_.slab.slipIntervals;
    return event(EventKind::SlipOnset) ? Step::Continue : Step::Done;
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
