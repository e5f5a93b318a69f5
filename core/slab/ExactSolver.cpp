// SPDX-License-Identifier: GPL-3.0-or-later
// Over 400 lines (with its header) for a reason: one run's state machine (stick, slip and
// the events between them), whose methods share the run's state; what stands alone is apart
// (core/slab/SegmentCuts, StopSample).
#include "core/slab/ExactSolver.h"

#include "core/numerics/HalleyRoot.h"
#include "core/numerics/RootFinding.h"
#include "core/numerics/VectorState.h"
#include "core/slab/FiniteResult.h"
#include "core/slab/SegmentCuts.h"
#include "core/slab/StopSample.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>

namespace kinstab {

namespace {

// Bounds the time line: a run that needs more half-periods (mu tiny against a slowly decaying
// envelope at a high frequency) is reported as failed after some seconds, not run for hours.
constexpr long kMaxSegments = 100'000'000;

class ExactRun {
public:
    ExactRun(const Excitation1D& a, const SlabParams& p, const RunOptions& o,
             SlabRecorder* recorder)
        : a_(a), p_(p), o_(o), recorder_(recorder) {}

    // The run, with the evaluations the excitation made for its own root solves (the |a| = mu
    // crossings) added to the work counter: every closed-form evaluation is counted.
    SlabResult run() {
        const long before = a_.threadEvaluations();
        runEvents();
        r_.work.accelEvaluations += a_.threadEvaluations() - before;
        return std::move(r_);
    }

private:
    enum class Step { Continue, Done };
    void runEvents();

    // Slip state relative to (t_, x_, v_) with slip sign s_.
    // The slip state at tau from the base motion's changes dv, dx since t_.
    double slipVelocity(double tau, double dv) const { return v_ - s_ * p_.mu * (tau - t_) - dv; }
    double slipDisplacement(double tau, double dx) const {
        const double h = tau - t_;
        return x_ + v_ * h - 0.5 * s_ * p_.mu * h * h - dx;
    }
    double velocityAt(double tau) {
        ++r_.work.accelEvaluations;
        return slipVelocity(tau, a_.velocityChange(t_, tau));
    }
    // The stop search's function s v and its first three derivatives at tau from one closed-form
    // evaluation: (s v)' = -mu - s a, (s v)'' = -s a', (s v)''' = -s a''. Where the excitation
    // does not know a' and a'' (a record), d3f is NaN and the search takes Newton's steps.
    void stopFunction(double tau, Derivatives& d) {
        ++r_.work.accelEvaluations;
        AccelAt& at = lastStop_.at;
        lastStop_.tau = tau;
        lastStop_.v = slipVelocity(tau, a_.velocityChangeAndSlopes(t_, tau, at));
        d.f = s_ * lastStop_.v;
        d.df = s_ * (-s_ * p_.mu - at.a);
        const bool slopes = !std::isnan(at.da) && !std::isnan(at.d2a);
        d.d2f = slopes ? -s_ * at.da : 0.0;
        d.d3f = slopes ? -s_ * at.d2a : std::numeric_limits<double>::quiet_NaN();
    }
    double displacementAt(double tau) {
        ++r_.work.accelEvaluations;
        return slipDisplacement(tau, a_.displacementChange(t_, tau));
    }
    // d(s v)/dtau = -mu - s a(tau) while slipping with sign s.
    double slipSlope(double tau) {
        ++r_.work.accelEvaluations;
        return -p_.mu - s_ * a_.accel(tau);
    }
    // velocityAt(tau), with displacementAt(tau) in x, from one closed-form evaluation.
    double velocityAndDisplacementAt(double tau, double& x) {
        ++r_.work.accelEvaluations;
        double dx = 0.0;
        const double dv = a_.velocityAndDisplacementChange(t_, tau, dx);
        x = slipDisplacement(tau, dx);
        return slipVelocity(tau, dv);
    }
    // The slip state at tau with a(tau), from one closed-form evaluation: a piece's end, whose
    // a gives the velocity's slope there to a stop search that ends at it.
    struct EndState {
        double tau = 0, x = 0, v = 0, a = 0;
    };
    EndState stateAt(double tau) {
        ++r_.work.accelEvaluations;
        EndState e{tau, 0.0, 0.0, 0.0};
        double dx = 0.0;
        const double dv = a_.changesAndAccel(t_, tau, dx, e.a);
        e.x = slipDisplacement(tau, dx);
        e.v = slipVelocity(tau, dv);
        return e;
    }
    // The state at the stop, with a there: from the stop search's last evaluation when the stop
    // is near it (core/slab/StopSample.h; its displacement from the memo's exponentials), else
    // from a new evaluation.
    EndState stopState(double tStop) {
        const StopSample& l = lastStop_;
        if (!l.reaches(tStop)) return stateAt(tStop);
        const double x = l.displacementAt(tStop, displacementAt(l.tau), s_, p_.mu);
        return {tStop, x, 0.0, l.accelAt(tStop)};
    }
    // slipSlope(tau) from a(tau) when an evaluation already made gave it (NaN: not known).
    double slipSlope(double tau, double knownAccel) {
        return std::isnan(knownAccel) ? slipSlope(tau) : -p_.mu - s_ * knownAccel;
    }
    // Sign of a where |a| > mu, else 0.
    int excessAt(double tau) {
        ++r_.work.accelEvaluations;
        const double a = a_.accel(tau);
        return std::abs(a) > p_.mu ? (a > 0.0 ? 1 : -1) : 0;
    }
    // How a stop is resolved: the piece knows whether |a| > mu all along it (Reverse) or not
    // (Stick); or a(tau) at the stop decides (Decide, for a slip with no cuts yet).
    enum class AtStop { Stick, Reverse, Decide };
    Step segment(double lo, double hi);
    Step hump(double hi, int sigma);
    Step slipAgainst(double hi);
    double nextOnset(double hi);
    Step cutIntoPieces(double lo, double hi);
    Step piece(double lo, double hi, int excess);
    Step slipThrough(double hi, AtStop atStop, const EndState* known = nullptr);
    Step slipTo(const EndState& end);
    bool collapsesBy(double tEnd, double xEnd, double vEnd);
    // accelAt: a(tau) where it is known without an evaluation (the level at a crossing).
    bool onset(double tau, int s, double accelAt = std::numeric_limits<double>::quiet_NaN()) {
        // The slab lags the walls, sliding against the acceleration.
        t_ = tau;
        aT_ = accelAt;
        s_ = s;
        ++r_.slipIntervals;
        return event(EventKind::SlipOnset, s_);
    }
    void moveTo(double tau, double x, double v,
                double accelAt = std::numeric_limits<double>::quiet_NaN()) {
        t_ = tau;
        x_ = x;
        v_ = v;
        aT_ = accelAt;
        r_.maxAbsDelta = std::max(r_.maxAbsDelta, std::abs(x));
    }
    bool event(EventKind kind, int direction) {
        ++r_.work.events;
        if (!std::isfinite(t_) || !std::isfinite(x_) || !std::isfinite(v_)) {
            // Never carry a NaN on: the next event search would have no bracket.
            finish(Outcome::Failed);
            r_.failure = std::string(kInternalFailure) + "non-finite state at " +
                         eventKindName(kind) + " event " + std::to_string(r_.work.events) +
                         " (tau " + std::to_string(t_) + ", delta " + std::to_string(x_) +
                         ", velocity " + std::to_string(v_) + ")";
            return false;
        }
        if (recorder_) recorder_->onEvent({t_, kind, x_, v_, direction});
        if (r_.work.events > o_.maxEvents) {
            finish(Outcome::Failed);
            r_.failure = "more than " + std::to_string(o_.maxEvents) + " events (chattering guard)";
            return false;
        }
        return true;
    }
    Step finish(Outcome outcome) {
        r_.outcome = outcome;
        r_.tauEnd = t_;
        r_.residualDelta = x_;
        return Step::Done;
    }
    // dflo, dfhi: the slopes at the ends. The functions are monotone on the bracket; starting
    // from the root of their Hermite cubic saves the first steps from the midpoint or the secant
    // point (every call costs closed-form integrals). fdf fills Derivatives: with d3f NaN (left
    // so by the collapse search) the steps are Newton's, else Halley's.
    double rootOf(auto&& fdf, double lo, double hi, double flo, double fhi, double dflo,
                  double dfhi) {
        const double start = hermiteRootGuess(lo, hi, flo, fhi, dflo, dfhi);
        const RootResult root =
            safeguardedHalley(fdf, lo, hi, flo, fhi, 200, start, o_.eventTolerance);
        r_.work.rootIterations += root.iterations;
        return std::clamp(root.x, lo, hi);
    }

    const Excitation1D& a_;
    const SlabParams& p_;
    const RunOptions& o_;
    SlabRecorder* recorder_; // null: nothing kept beyond the result
    SlabResult r_;
    double t_ = 0, x_ = 0, v_ = 0;
    // a(t_) when the evaluation that moved the slip to t_ gave it, else NaN: the stop search
    // from t_ takes the velocity's slope at t_ from it instead of evaluating a again.
    double aT_ = std::numeric_limits<double>::quiet_NaN();
    StopSample lastStop_; // the stop search's last evaluation
    int s_ = 0;           // 0 sticking, +1/-1 slipping with that sign of relative velocity
};

void ExactRun::runEvents() {
    const double end = p_.duration.value_or(std::numeric_limits<double>::infinity());
    if (!p_.duration && a_.boundAfter(std::numeric_limits<double>::infinity()) >= p_.mu) {
        r_.failure = "the excitation never decays below mu: set a duration (tau_out)";
        finish(Outcome::Failed);
        return;
    }
    double segStart = 0.0;
    while (true) {
        if (s_ == 0 && a_.boundAfter(segStart) < p_.mu) {
            t_ = std::max(t_, segStart);
            event(EventKind::Stable, 0);
            finish(Outcome::Stable);
            return;
        }
        if (segStart >= end) {
            // The run ends at the cap, sticking or slipping.
            if (s_ != 0)
                moveTo(end, displacementAt(end), velocityAt(end));
            else
                t_ = end;
            event(EventKind::DurationCap, s_);
            finish(Outcome::Stable);
            return;
        }
        const double segEnd = std::min(a_.segmentEnd(segStart), end);
        if (!(segEnd > segStart) || ++r_.work.steps > kMaxSegments) {
            t_ = segStart;
            finish(Outcome::Failed);
            r_.failure = !(segEnd > segStart)
                             ? std::string(kInternalFailure) + "the time line stalls at tau " +
                                   std::to_string(segStart)
                             : "more than " + std::to_string(kMaxSegments) +
                                   " segments (half-periods) before the excitation decays below "
                                   "mu: set a shorter duration";
            return;
        }
        if (segment(segStart, segEnd) == Step::Done) return;
        segStart = segEnd;
    }
}

ExactRun::Step ExactRun::segment(double lo, double hi) {
    if (s_ == 0 && a_.boundOn(lo, hi) <= p_.mu) return Step::Continue; // nothing can start
    const int sigma = a_.humpSign(lo, hi);
    if (sigma == 0 || p_.mu <= 0.0) return cutIntoPieces(lo, hi);
    if (s_ == 0) t_ = std::max(t_, lo); // stuck since an earlier segment: wait here
    return hump(hi, sigma);
}

// One hump of a (sign sigma; |a| rises through mu at c1 and falls through it at c2) from t_ to
// hi, asking only for the crossing an event needs. With s v' = -mu - s a:
//  - sticking: the slab slides (s = -sigma) at the first time |a| > mu;
//  - s = sigma: s v falls throughout, so the stop needs no crossing and a there decides
//    between sticking and sliding straight back;
//  - s = -sigma from before c1: s v falls until c1 (a stop there sticks), then slides on.
ExactRun::Step ExactRun::hump(double hi, int sigma) {
    while (t_ < hi) {
        if (s_ == 0) {
            const double tOnset = nextOnset(hi);
            if (!std::isfinite(tOnset)) return Step::Continue; // stuck through the hump
            const bool atCrossing = tOnset > t_;               // else at t_, a grazing restart
            if (!onset(tOnset, -sigma,
                       atCrossing ? sigma * p_.mu : std::numeric_limits<double>::quiet_NaN()))
                return Step::Done;
        } else if (s_ == sigma) {
            if (slipThrough(hi, AtStop::Decide) == Step::Done) return Step::Done;
            if (s_ != -sigma) continue; // through to hi, or stuck: look for the next onset
        } else {
            const double c1 = a_.humpCrossing(p_.mu, t_, hi, true);
            if (!std::isfinite(c1)) return slipThrough(hi, AtStop::Stick);
            if (slipThrough(c1, AtStop::Stick) == Step::Done) return Step::Done;
            if (s_ == 0 && !onset(c1, -sigma, sigma * p_.mu)) return Step::Done;
        }
        // Sliding against a at t_ inside [c1, c2] (just started, reversed, or carried in).
        if (slipAgainst(hi) == Step::Done) return Step::Done;
    }
    return Step::Continue;
}

// The first time from t_ on where |a| > mu on the hump: its rising crossing, or t_ itself when
// t_ is already past it and still above mu (a stop a rounding error away from a crossing) with
// the falling crossing still ahead. Where the hump only grazes mu, |a(t_)| may exceed mu by a
// rounding error with no crossing left after t_: no onset then, or the slab would slide and stop
// at t_ forever.
double ExactRun::nextOnset(double hi) {
    constexpr double none = std::numeric_limits<double>::quiet_NaN();
    const double c1 = a_.humpCrossing(p_.mu, t_, hi, true);
    if (std::isfinite(c1)) return c1;
    if (excessAt(t_) == 0) return none;
    return std::isfinite(a_.humpCrossing(p_.mu, t_, hi, false)) ? t_ : none;
}

// Sliding against a from t_ in [c1, c2]: s v rises until c2, then falls, so it cannot stop
// before hi if it is still positive there; only otherwise is c2 needed, to bracket the stop.
// The state at hi found first stays the end of the stop search after c2, unless an event on
// the way to c2 changed the slip.
ExactRun::Step ExactRun::slipAgainst(double hi) {
    const EndState atHi = stateAt(hi);
    if (s_ * atHi.v > 0.0) return slipTo(atHi);
    const double c2 = a_.humpCrossing(p_.mu, t_, hi, false);
    const long events = r_.work.events;
    if (std::isfinite(c2) && slipThrough(c2, AtStop::Reverse) == Step::Done) return Step::Done;
    return slipThrough(hi, AtStop::Stick, r_.work.events == events ? &atHi : nullptr);
}

// Cut [lo, hi] at every crossing of |a| = mu (core/slab/SegmentCuts.h), then each piece has a
// fixed sign of |a| - mu and of a +- mu, carried through the cuts.
ExactRun::Step ExactRun::cutIntoPieces(double lo, double hi) {
    const SegmentCuts c = segmentCuts(a_, p_.mu, lo, hi);
    int state = firstPieceExcess(c, [&](double tau) { return excessAt(tau); });
    for (std::size_t i = 0; i + 1 < c.n; ++i) {
        if (i > 0) {
            const auto next = crossCut(state, c.cut[i].kind);
            state = next ? *next : excessAt(0.5 * (c.cut[i].tau + c.cut[i + 1].tau));
        }
        if (c.cut[i + 1].tau <= c.cut[i].tau) continue;
        if (piece(c.cut[i].tau, c.cut[i + 1].tau, state) == Step::Done) return Step::Done;
    }
    return Step::Continue;
}

// excess: the sign of a where |a| > mu on the piece, 0 where |a| <= mu.
ExactRun::Step ExactRun::piece(double lo, double hi, int excess) {
    if (s_ == 0) {
        if (excess == 0) return Step::Continue;
        if (!onset(lo, -excess)) return Step::Done;
    }
    return slipThrough(hi, excess != 0 ? AtStop::Reverse : AtStop::Stick);
}

// Slip from t_ to hi (inside one piece); handles a stop, a reversal and collapse. With
// AtStop::Decide it returns at the first stop (t_ < hi then). known: the slip's state at hi,
// already evaluated from an earlier point of the same slip.
ExactRun::Step ExactRun::slipThrough(double hi, AtStop atStop, const EndState* known) {
    while (true) {
        const EndState atHi = known ? *known : stateAt(hi);
        known = nullptr; // a reversal below starts another slip
        const double vHi = atHi.v;
        const bool stops = s_ * vHi <= 0.0 && !(atStop == AtStop::Reverse && v_ == 0.0);
        if (!stops) return slipTo(atHi);
        // s v <= 0 already at t_ only through rounding right after a grazing onset: stop there.
        lastStop_ = StopSample{};
        const double tStop =
            (s_ * v_ <= 0.0)
                ? t_
                : rootOf([&](double tau, Derivatives& d) { stopFunction(tau, d); }, t_, hi, s_ * v_,
                         s_ * vHi, slipSlope(t_, aT_), slipSlope(hi, atHi.a));
        // The state at the stop, with a there (whether it sticks, and the next slip's slope).
        const EndState stop = stopState(tStop);
        if (collapsesBy(tStop, stop.x, 0.0)) return Step::Done;
        moveTo(tStop, stop.x, 0.0, stop.a);
        if (atStop == AtStop::Reverse || (atStop == AtStop::Decide && std::abs(stop.a) > p_.mu)) {
            // |a| > mu at the stop: no sticking, it slides back at once (docs/theory.md §6.6 case
            // 5).
            s_ = -s_;
            ++r_.slipIntervals;
            if (!event(EventKind::Reversal, s_)) return Step::Done;
            if (atStop == AtStop::Decide) return Step::Continue;
            continue;
        }
        s_ = 0;
        if (!event(EventKind::Stick, 0)) return Step::Done;
        return Step::Continue;
    }
}

// The slip reaches the end state without stopping, unless it collapses on the way.
ExactRun::Step ExactRun::slipTo(const EndState& end) {
    if (collapsesBy(end.tau, end.x, end.v)) return Step::Done;
    moveTo(end.tau, end.x, end.v, end.a);
    return Step::Continue;
}

// Whether the slip from t_ passes the limit by tEnd; if so, ends the run at that time. The
// displacement is monotone while the slip keeps its sign: one crossing of the limit.
bool ExactRun::collapsesBy(double tEnd, double xEnd, double vEnd) {
    if (!(s_ * xEnd > p_.limit)) return false;
    const double tC = rootOf(
        [&](double tau, Derivatives& d) {
            double x = 0.0;
            d.df = s_ * velocityAndDisplacementAt(tau, x);
            d.f = s_ * x - p_.limit;
        },
        t_, tEnd, s_ * x_ - p_.limit, s_ * xEnd - p_.limit, s_ * v_, s_ * vEnd);
    moveTo(tC, s_ * p_.limit, velocityAt(tC));
    r_.tauC = tC;
    if (event(EventKind::Collapse, s_)) finish(Outcome::Collapsed);
    return true;
}

} // namespace

SlabResult solveExact(const Excitation1D& excitation, const SlabParams& params,
                      const RunOptions& options, SlabRecorder* recorder) {
    clearUpperVectorState(); // see VectorState.h: a host process may leave AVX state dirty
    SlabResult r = ExactRun(excitation, params, options, recorder).run();
    failIfNonFinite(r);
    return r;
}

} // namespace kinstab
