// SPDX-License-Identifier: GPL-3.0-or-later
// A planar slip's steps on the full equations: DOP853, or five-stage Radau IIA where the slip is
// stiff (core/slab/SlipRadau.h), with the walls' events located on the step's dense output.
#include "core/slab/PlanarRun.h"

#include "core/numerics/RadauIIA.h"

#include <algorithm>
#include <cmath>

namespace kinstab::planar {

namespace {
// A Radau IIA step whose Newton iteration failed is retried at half its length (RADAU5's choice,
// Hairer & Wanner 1996, IV.8).
constexpr double kNewtonFailureRetry = 0.5;
// A step over which the velocity turned over is retaken at half its length, until the stop ahead
// is predicted and approached in s.
constexpr double kTurnoverRetry = 0.5;
} // namespace

Vec4 PlanarRun::rhs(double tau, const Vec4& y) {
    ++r_.slab.work.accelEvaluations;
    const Vec2 a = m_.accel(tau);
    const double n = m_.normal(tau);
    const double rho = norm2(y[2], y[3]);
    double ex = 0, ey = 0;
    if (rho > 0.0) {
        ex = y[2] / rho;
        ey = y[3] / rho;
    } else if (const double am = norm2(a.x, a.y); am > 0.0) {
        ex = -a.x / am; // at rest the slab starts along -a_h
        ey = -a.y / am;
    }
    Vec4 f;
    f << y[2], y[3], -mu_ * n * ex - a.x, -mu_ * n * ey - a.y;
    return f;
}

// Slides from t_ to end, or until the slab sticks (then returns with slipping_ false).
PlanarRun::Step PlanarRun::slipTo(double end) {
    rejected_ = true;
    lastImplicit_ = false;
    while (t_ < end) {
        const double rho = norm2(y_[2], y_[3]);
        if (isSlaved(t_, y_)) {
            const Step s = slaved(end);
            if (s == Step::Done || !slipping_) return s;
            continue;
        }
        // The derivative at the state an accepted step ended on is that step's last stage (FSAL).
        const Vec4 f0 = t_ == fsalT_ && y_ == fsalY_ ? fsalF_ : rhs(t_, y_);
        const double d = -(y_[2] * f0[2] + y_[3] * f0[3]) / rho; // -d|u|/dtau
        // Without a proposal: the time |u| takes to change by itself at a rate of about mu + 1.
        double h = std::min(hNext_ > 0.0 ? hNext_ : rho / (mu_ + 1.0), end - t_);
        const bool implicit = isStiff(t_, rho);
        if (d > 0.0 && rho <= d * h) { // a stop predicted within the step
            switch (stopAhead(end, d, rho, implicit, h)) {
            case Flow::TakeStep:
                break;
            case Flow::Again:
                continue;
            case Flow::Return:
                return Step::Continue;
            case Flow::Done:
                return Step::Done;
            }
        }
        if (++r_.slab.work.steps > o_.maxSteps) return fail("step limit reached");
        if (step(implicit, f0, h) == Step::Done) return Step::Done;
    }
    return Step::Continue;
}

// A stop predicted within the next step of length h at speed rho falling at rate d.
PlanarRun::Flow PlanarRun::stopAhead(double end, double d, double rho, bool implicit, double& h) {
    if (implicit && rho > slavedSpeed_ && onManifold(t_, y_, kImplicitStopAngle)) {
        // On the slow manifold |u| falls about linearly while its direction follows -a_h;
        // the implicit steps go down to the slaved speed, which locates the stop.
        h = kStopHalfway * rho / d;
        return Flow::TakeStep;
    }
    // Off it: go on in s = ln|u|.
    switch (approachStop(end)) {
    case Approach::Done:
        return Flow::Done;
    case Approach::ReachedEnd:
        return Flow::Return;
    case Approach::Exited:
        return Flow::Again;
    case Approach::Stopped:
        if (afterStop() == Step::Done) return Flow::Done;
        return slipping_ ? Flow::Again : Flow::Return;
    }
    return Flow::Again;
}

// One trial step of length h from the current state: accepted, retaken shorter, or ended at a
// collapse located inside it.
PlanarRun::Step PlanarRun::step(bool implicit, const Vec4& f0, double h) {
    const Trial st = trial(implicit, t_, y_, f0, h, rejected_ || implicit != lastImplicit_);
    lastImplicit_ = implicit;
    rejected_ = !(st.err <= 1.0);
    if (rejected_) {
        ++r_.slab.work.restarts;
        hNext_ = h * st.retry;
        if (hNext_ < kStepUnderflow * std::max(1.0, t_))
            return fail("step size underflow in a slip");
        return Step::Continue;
    }
    const StateEvent* wall = firstFired(walls_, st.y);
    const StepExtrema extrema = stepExtrema(h, y_, st.y, st.poly);
    if (retakeForOvershoot(extrema, h, wall != nullptr)) return Step::Continue;
    if (wall) return collapseInStep(*wall, implicit, f0, h, st.y);
    if (st.y[2] * y_[2] + st.y[3] * y_[3] < 0.0) {
        // The velocity turned over within one step: it passed a stop; retake it shorter so
        // the stop is approached in s.
        ++r_.slab.work.restarts;
        hNext_ = kTurnoverRetry * h;
        return Step::Continue;
    }
    accept(st, h, implicit, extrema);
    return Step::Continue;
}

// One step of the slip equations from (t0, y0), explicit (DOP853) or implicit (Radau IIA),
// with its error norm and the factors for the next step or the retry.
PlanarRun::Trial PlanarRun::trial(bool implicit, double t0, const Vec4& y0, const Vec4& f0,
                                  double h, bool refine) {
    const Vec4 absTol = Vec4::Constant(o_.absTol);
    if (implicit) {
        // The previous step's polynomial is used only when it ended at t0 (slipRadauStep checks).
        const SlipRadauStep st = slipRadauStep(m_, t0, y0, f0, h, absTol, radauTol_, refine,
                                               lastPoly_.h > 0.0 ? &lastPoly_ : nullptr);
        r_.slab.work.accelEvaluations += st.evaluations;
        r_.slab.work.rootIterations += st.newton;
        const double factor = radau::stepFactor(st.err, st.newton, kSlipRadauMaxNewton);
        const double retry = std::isfinite(st.err) ? factor : kNewtonFailureRetry;
        return {st.y, st.f, st.err, factor, retry, st.poly};
    }
    const auto st =
        dop853Step<4, 2, 2>([&](double t, const Vec4& y) { return rhs(t, y); }, t0, y0, f0, h);
    const double err = dop853ErrorNorm<4>(st, y0, absTol, o_.relTol);
    return {st.y, st.f, err, dop853StepFactor(err), dop853RetryStep(h, err) / h, {}};
}

// Whether a slip at speed rho is left to the implicit step: the explicit one's stability bound,
// about 6 |u| / (mu n) (the Jacobian's eigenvalue is -mu n / |u|), then falls below a few
// hundredths of the horizontal time scale T, about its accuracy step at the default tolerance.
// With the five-stage Radau IIA step the threshold |u| < 0.04 mu n T costs least on the 33x33
// bench grid (instructions: 0.03 and 0.06 within 1 %, 0.02 3 % and 0.01 9 % more; docs/theory.md
// §6.5); with three stages 0.02 had been the fastest.
bool PlanarRun::isStiff(double tau, double rho) const {
    return rho < stiffSpeed_ * m_.normal(tau);
}

// A step whose ends are inside the walls can still pass an edge between them and come back:
// a grazing collapse that a check of the step's end misses. When the interpolant's extremum
// lies beyond an edge, the step is retaken to end just past it, where the end check sees the
// collapse and locates it.
bool PlanarRun::retakeForOvershoot(const StepExtrema& ex, double h, bool endsOutside) {
    const double s = endsOutside ? 0.0 : overshootWithin(ex);
    if (!(s > 0.0 && s * h > kStepUnderflow * std::max(1.0, t_))) return false;
    ++r_.slab.work.restarts;
    hNext_ = s * h * (1.0 + kPastExtremum);
    return true;
}

// The wall edge of displacement component c: the bearing limit across, Θ along the walls.
double PlanarRun::edge(int c) const {
    return c == 0 ? m_.params().limit : m_.params().theta;
}

// The fraction of the step at which an extremum lies beyond an edge (the first one), or 0 when
// the step stays inside.
double PlanarRun::overshootWithin(const StepExtrema& ex) const {
    double first = 0.0;
    for (int c = 0; c < 2; ++c)
        if (ex[c] && std::abs(ex[c]->value) > edge(c) && ex[c]->fraction > 0.0)
            first = first > 0.0 ? std::min(first, ex[c]->fraction) : ex[c]->fraction;
    return first;
}

// Max |dx| and |dy| inside an accepted step, not the step ends only.
void PlanarRun::extremaWithin(const StepExtrema& ex) {
    if (ex[0]) r_.slab.maxAbsDelta = std::max(r_.slab.maxAbsDelta, std::abs(ex[0]->value));
    if (ex[1]) r_.maxAbsDeltaY = std::max(r_.maxAbsDeltaY, std::abs(ex[1]->value));
}

// The wall event e fired at the end of the step of length h from the current state: its time
// located on the step's dense output (the step re-taken to each trial time).
PlanarRun::Step PlanarRun::collapseInStep(const StateEvent& e, bool implicit, const Vec4& f0,
                                          double h, const Vec4& yEnd) {
    const Vec4 y0 = y_;
    const double t0 = t_;
    const int c = e.component;
    const double tc = locateEvent(
        e,
        [&](double t, double& yk, double& dyk) {
            const Trial s = trial(implicit, t0, y0, f0, t - t0, true);
            yk = s.y[c];
            dyk = s.y[c + 2];
        },
        t0, t0 + h, e.value(y0[c]), e.value(yEnd[c]), r_.slab.work.rootIterations);
    return collapse(tc, trial(implicit, t0, y0, f0, tc - t0, true).y, e);
}

// An accepted step: its extrema, the next step's length and the FSAL state.
void PlanarRun::accept(const Trial& st, double h, bool implicit, const StepExtrema& extrema) {
    const bool truncated = h < hNext_;
    extremaWithin(extrema);
    double grow = h * st.grow;
    if (fsalT_ == t_ && lastStep_.implicit == implicit) {
        const double errPrev = lastStep_.err, hPrev = lastStep_.h;
        grow = std::min(grow, h * (implicit ? radau::predictiveFactor(h, st.err, hPrev, errPrev)
                                            : dop853PredictiveFactor(h, st.err, hPrev, errPrev)));
    }
    lastStep_ = {h, std::max(kErrorFloor, st.err), implicit};
    moveTo(t_ + h, st.y);
    fsalT_ = t_;
    fsalY_ = y_;
    fsalF_ = st.f;
    lastPoly_ = st.poly;
    hNext_ = truncated ? std::max(hNext_, grow) : grow;
}

PlanarRun::Step PlanarRun::collapse(double tau, const Vec4& y, const StateEvent& e) {
    moveTo(tau, y);
    r_.slab.tauC = tau;
    r_.exitSide = e.kind == StateKind::CollapseAlong ? ExitSide::Along : ExitSide::Across;
    if (!event(EventKind::Collapse)) return Step::Done;
    return finish(Outcome::Collapsed);
}

} // namespace kinstab::planar
