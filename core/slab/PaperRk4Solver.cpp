// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/slab/PaperRk4Solver.h"

#include "core/numerics/VectorState.h"
#include "core/slab/FiniteResult.h"

#include <array>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

namespace kinstab {

namespace {

// (y_b, y_b', y_s, y_s'): walls and slab, as the paper integrates them.
using State = std::array<double, 4>;

struct Sample {
    double tau;
    double relVelocity; // y_s' - y_b'
};

class PaperRun {
public:
    // keepEvents: hold this attempt's events until it is known to succeed (a failed attempt
    // restarts from the beginning, and its events are none of the run's).
    PaperRun(const Excitation1D& a, const SlabParams& p, double h, const RunOptions& o,
             long maxSteps, bool keepEvents)
        : a_(a), p_(p), h_(h), o_(o), maxSteps_(maxSteps), keepEvents_(keepEvents) {}

    // nullopt: a failure to locate an event (the caller restarts with H/4).
    std::optional<SlabResult> run();
    const SolverWork& work() const { return r_.work; }
    const std::vector<SlabEvent>& events() const { return events_; }

private:
    double accel(double tau) {
        ++r_.work.accelEvaluations;
        return a_.accel(tau);
    }
    State rhs(double tau, const State& y) {
        const double a = accel(tau);
        double slab = a;
        // Friction keeps the slip's direction through the whole step, as the paper's code does:
        // the slab's velocity then overshoots, which is what makes the relative velocity change
        // sign at a stop ("Test for sticking"). A sgn(v) in the stages would chatter instead.
        if (sliding_) slab = -p_.mu * direction_;
        return {y[1], a, y[3], slab};
    }
    State rk4(double tau, const State& y, double h) {
        auto axpy = [](const State& y0, const State& k, double c) {
            return State{y0[0] + c * k[0], y0[1] + c * k[1], y0[2] + c * k[2], y0[3] + c * k[3]};
        };
        const State k1 = rhs(tau, y);
        const State k2 = rhs(tau + 0.5 * h, axpy(y, k1, 0.5 * h));
        const State k3 = rhs(tau + 0.5 * h, axpy(y, k2, 0.5 * h));
        const State k4 = rhs(tau + h, axpy(y, k3, h));
        State out;
        for (std::size_t i = 0; i < 4; ++i)
            out[i] = y[i] + h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
        ++r_.work.steps;
        return out;
    }
    std::optional<double> slipTime(double tPrev, double tNow);
    std::optional<double> stickTime(double tPrev, double tNow);
    bool endsBeforeStep(double tau, const State& y, double end, long& n);
    bool endsAfterStep(double tau, const State& y);
    bool locateEvents(double tPrev, const State& yPrev, double tNow, State& y);
    bool startSlip(double tPrev, const State& yPrev, double tNow, State& y);
    bool stopOrReverse(double tPrev, const State& yPrev, double tNow, double aNow, State& y);
    // The run's end: always true, for the callers' return.
    bool finish(Outcome o, double tEnd, const State& y) {
        r_.outcome = o;
        r_.tauEnd = tEnd;
        r_.residualDelta = y[2] - y[0];
        return true;
    }
    void record(EventKind kind, double tau, const State& y, int direction) {
        ++r_.work.events;
        if (keepEvents_) events_.push_back({tau, kind, y[2] - y[0], y[3] - y[1], direction});
    }

    const Excitation1D& a_;
    const SlabParams& p_;
    double h_;
    const RunOptions& o_;
    long maxSteps_;
    bool keepEvents_;
    std::vector<SlabEvent> events_;
    SlabResult r_;
    bool sliding_ = false;
    double direction_ = 0.0;
    std::array<Sample, 3> last_{}; // the three most recent (tau, relative velocity)
};

// Newton on |a(tau)| - mu from the step's midpoint; correction < 1e-6; at most 10 iterations;
// the root must lie in the step (Appendix, "Test for slipping").
std::optional<double> PaperRun::slipTime(double tPrev, double tNow) {
    double tau = tPrev + 0.5 * (tNow - tPrev);
    for (int it = 0; it < 10; ++it) {
        ++r_.work.rootIterations;
        const double a = accel(tau);
        const double slope = a_.accelSlope(tau) * (a >= 0.0 ? 1.0 : -1.0);
        if (slope == 0.0) return std::nullopt;
        const double dt = (std::abs(a) - p_.mu) / slope;
        tau -= dt;
        if (std::abs(dt) < 1e-6) {
            if (tau > tPrev && tau < tNow) return tau;
            return std::nullopt;
        }
    }
    return std::nullopt;
}

// Quadratic through the last three relative velocities by divided differences; its root in the
// step, chosen as the paper does (stable formula, product of roots for the other).
std::optional<double> PaperRun::stickTime(double tPrev, double tNow) {
    const auto& [s0, s1, s2] = last_;
    const double d01 = (s1.relVelocity - s0.relVelocity) / (s1.tau - s0.tau);
    const double d12 = (s2.relVelocity - s1.relVelocity) / (s2.tau - s1.tau);
    const double d012 = (d12 - d01) / (s2.tau - s0.tau);
    // p(t) = v0 + d01 (t - t0) + d012 (t - t0)(t - t1), in u = t - t2 for conditioning.
    const double u0 = s0.tau - s2.tau, u1 = s1.tau - s2.tau;
    const double qa = d012;
    const double qb = d01 + d012 * (-u0 - u1);
    const double qc = s0.relVelocity - d01 * u0 + d012 * u0 * u1;
    const double lo = tPrev - s2.tau, hi = tNow - s2.tau;
    auto inStep = [&](double u) { return std::isfinite(u) && u >= lo && u <= hi; };
    ++r_.work.rootIterations;
    if (qa == 0.0) {
        const double u = -qc / qb;
        if (inStep(u)) return s2.tau + u;
        return std::nullopt;
    }
    const double disc = qb * qb - 4.0 * qa * qc;
    if (disc < 0.0) return std::nullopt;
    const double qq = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
    const double first = qq / qa;
    const double second = qq != 0.0 ? qc / qq : first;
    if (inStep(first)) return s2.tau + first;
    if (inStep(second)) return s2.tau + second;
    return std::nullopt;
}

// Before step n: the run ends (r_ holds the result) when the excitation has decayed below mu
// while sticking, the duration is reached, or the step budget is spent.
bool PaperRun::endsBeforeStep(double tau, const State& y, double end, long& n) {
    if (!sliding_ && a_.boundAfter(tau) < p_.mu) {
        record(EventKind::Stable, tau, y, 0);
        return finish(Outcome::Stable, tau, y);
    }
    if (tau >= end) {
        record(EventKind::DurationCap, tau, y, 0);
        return finish(Outcome::Stable, tau, y);
    }
    if (++n > maxSteps_) {
        r_.failure = "step limit reached";
        return finish(Outcome::Failed, tau, y);
    }
    return false;
}

// After a step: the run ends (r_ holds the result) on collapse, tested at step ends only, or on
// too many events.
bool PaperRun::endsAfterStep(double tau, const State& y) {
    const double delta = y[2] - y[0];
    r_.maxAbsDelta = std::max(r_.maxAbsDelta, std::abs(delta));
    if (std::abs(delta) > p_.limit) {
        // The paper takes the time of the present step as the collapse time.
        r_.tauC = tau;
        record(EventKind::Collapse, tau, y, static_cast<int>(direction_));
        return finish(Outcome::Collapsed, tau, y);
    }
    if (r_.work.events > o_.maxEvents) {
        r_.failure = "event limit reached";
        return finish(Outcome::Failed, tau, y);
    }
    return false;
}

// Slip onset inside the step [tPrev, tNow]: stepped again to the onset, then on to tNow sliding.
// false: the onset was not located.
bool PaperRun::startSlip(double tPrev, const State& yPrev, double tNow, State& y) {
    const auto ts = slipTime(tPrev, tNow);
    if (!ts) return false;
    // Sticking up to the onset: the slab moves with the walls.
    State ySlip = rk4(tPrev, yPrev, *ts - tPrev);
    sliding_ = true;
    direction_ = accel(*ts) > 0.0 ? -1.0 : 1.0;
    ++r_.slipIntervals;
    record(EventKind::SlipOnset, *ts, ySlip, static_cast<int>(direction_));
    y = rk4(*ts, ySlip, tNow - *ts);
    last_[2] = Sample{tNow, y[3] - y[1]};
    return true;
}

// A sliding step whose relative velocity changed sign: a reversal while |a| >= mu, else a stick
// (stepped again to the stick time, then on to tNow stuck). false: the stick was not located.
bool PaperRun::stopOrReverse(double tPrev, const State& yPrev, double tNow, double aNow, State& y) {
    const double dvNow = y[3] - y[1];
    const bool stopped = direction_ * dvNow <= 0.0;
    if (stopped && std::abs(aNow) >= p_.mu) {
        // The paper's text marches on here; we let the slab slide back (a reversal).
        direction_ = -direction_;
        ++r_.slipIntervals;
        record(EventKind::Reversal, tNow, y, static_cast<int>(direction_));
    } else if (stopped) {
        const auto ts = stickTime(tPrev, tNow);
        if (!ts) return false;
        State yStick = rk4(tPrev, yPrev, *ts - tPrev);
        yStick[3] = yStick[1]; // stuck: slab and walls share the velocity
        sliding_ = false;
        record(EventKind::Stick, *ts, yStick, 0);
        y = rk4(*ts, yStick, tNow - *ts);
        last_[2] = Sample{tNow, y[3] - y[1]};
    }
    return true;
}

// The events inside the step just taken (y: its end state, redone from the event on when one
// happened). false: an event was not located.
bool PaperRun::locateEvents(double tPrev, const State& yPrev, double tNow, State& y) {
    const double aNow = accel(tNow);
    last_ = {last_[1], last_[2], Sample{tNow, y[3] - y[1]}};
    if (!sliding_ && std::abs(aNow) > p_.mu) return startSlip(tPrev, yPrev, tNow, y);
    if (sliding_) return stopOrReverse(tPrev, yPrev, tNow, aNow, y);
    return true;
}

std::optional<SlabResult> PaperRun::run() {
    const double end = p_.duration.value_or(std::numeric_limits<double>::infinity());
    if (!p_.duration && a_.boundAfter(std::numeric_limits<double>::infinity()) >= p_.mu) {
        r_.outcome = Outcome::Failed;
        r_.failure = "the excitation never decays below mu: set a duration (tau_out)";
        return r_;
    }
    State y{0, 0, 0, 0};
    double tau = 0.0;
    last_.fill({0.0, 0.0});
    // The first step is H/2, so that three points exist for the quadratic (Appendix).
    double h = 0.5 * h_;
    long n = 0;
    while (true) {
        if (endsBeforeStep(tau, y, end, n)) return r_;
        const double tPrev = tau;
        const State yPrev = y;
        const double tNow = tPrev + h;
        y = rk4(tPrev, yPrev, h);
        if (!locateEvents(tPrev, yPrev, tNow, y)) return std::nullopt;
        tau = tNow;
        if (endsAfterStep(tau, y)) return r_;
        h = h_;
    }
}

} // namespace

SlabResult solvePaperRk4(const Excitation1D& excitation, const SlabParams& params,
                         const PaperSettings& settings, const RunOptions& options,
                         SlabRecorder* recorder) {
    clearUpperVectorState(); // see VectorState.h: a host process may leave AVX state dirty
    SolverWork total;
    double h = settings.step;
    for (int failures = 0;; ++failures) {
        PaperRun run(excitation, params, h, options, settings.maxSteps, recorder != nullptr);
        std::optional<SlabResult> r = run.run();
        if (r) {
            r->work.accelEvaluations += total.accelEvaluations;
            r->work.rootIterations += total.rootIterations;
            r->work.steps += total.steps;
            r->work.restarts = failures;
            failIfNonFinite(*r, run.events());
            if (recorder)
                for (const SlabEvent& e : run.events())
                    recorder->onEvent(e);
            return *r;
        }
        total.accelEvaluations += run.work().accelEvaluations;
        total.rootIterations += run.work().rootIterations;
        total.steps += run.work().steps;
        if (failures + 1 >= settings.maxFailures) {
            SlabResult failed;
            failed.outcome = Outcome::Failed;
            failed.failure = "paper solver: event not located after " +
                             std::to_string(settings.maxFailures) + " attempts (H down to " +
                             std::to_string(h) + ")";
            failed.work = total;
            failed.work.restarts = failures + 1;
            return failed;
        }
        h *= 0.25;
    }
}

} // namespace kinstab
