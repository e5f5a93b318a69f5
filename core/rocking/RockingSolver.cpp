// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/rocking/RockingSolver.h"

#include "core/base/PhysicalConstants.h"
#include "core/numerics/Dop853.h"
#include "core/numerics/RootFinding.h"
#include "core/rocking/FreeRocking.h"
#include "core/rocking/RockingDynamics.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace kinstab {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kHalfPi = 0.5 * std::numbers::pi;
// Free rocking that can no longer overturn is followed this many impacts after the base motion
// has ended when no duration is given (with eta = 1 it would rock for ever).
constexpr int kImpactsAfterEnd = 200;
// Rebounds whose heights, all of them summed, stay below this (times alpha) are rest: a block
// bouncing on its base against gravity comes to rest after infinitely many impacts in a finite
// time (Zeno), and its remaining motion is below what a step resolves.
constexpr double kRestHeight = 1e-9;
// A rebound slower than this (times p alpha) is rest whatever the base does.
constexpr double kRestRebound = 1e-9;

double sgn(double x) {
    return x < 0.0 ? -1.0 : 1.0;
}

// The events a step can end on. Apex (theta' = 0 outwards) changes nothing but the maximum.
enum class Event { None, Impact, Overturn, Normal, Friction, SlideStop, Apex };

// One run: the state, the mode, and what happened so far.
class Run {
public:
    Run(const RockingModel& m, const BaseMotion& motion, const RockingRunOptions& o);
    RockingResult go();

private:
    BaseAccel baseAt(double t) const { return {motion_.horizontal(t), motion_.vertical(t)}; }
    BlockState derivative(double t, const BlockState& y) const {
        return blockDerivative(k_, mode_, z_, sigma_, y, baseAt(t));
    }
    // The value of an event function at (t, y, f = y'), and its time derivative when cheap
    // (0 when not: the root search then bisects).
    double eventValue(Event e, double t, const BlockState& y, const BlockState& f,
                      double* slope) const;
    bool restPhase();
    bool integrate();
    bool finishSliding();
    void accept(double t1, const BlockState& y1);
    bool locateAndApply(double t0, const BlockState& y0, const BlockState& f0, double h,
                        const BlockState& y1, const BlockState& f1);
    double locate(Event e, double t0, const BlockState& y0, const BlockState& f0, double h,
                  double g0, double s0, double g1, double s1);
    BlockState stepTo(double t0, const BlockState& y0, const BlockState& f0, double s) const;
    bool apply(Event e);
    bool startMode(BlockMode mode);
    bool afterImpact();
    bool reboundDies() const;
    void decideFree();
    void record(double t, const BlockState& y);
    void recordUpTo(double t0, const BlockState& y0, const BlockState& f0, double t1);
    void countEvent();
    void seeTheta(double theta) {
        r_.maxThetaOverAlpha = std::max(r_.maxThetaOverAlpha, std::abs(theta) / k_.alpha);
    }

    const BaseMotion& motion_;
    const RockingRunOptions& o_;
    BlockConstants k_;
    double eta_;
    double rockLevel_; // |a_h| / (1 + a_v) that lifts a corner: tan alpha, or alpha
    bool canSlide_;
    double endT_, stopT_;
    bool hasDuration_;
    BlockState absTol_;

    double t_ = 0.0;
    BlockState y_ = BlockState::Zero();
    BlockMode mode_ = BlockMode::Rest;
    double z_ = 1.0, sigma_ = 1.0;
    double h_ = 0.0;
    bool decided_ = false, stop_ = false, overturned_ = false, left_ = false;
    int impactsAfterEnd_ = 0;
    double nextSample_ = 0.0;
    RockingResult r_;
};

Run::Run(const RockingModel& m, const BaseMotion& motion, const RockingRunOptions& o)
    : motion_(motion), o_(o), k_(blockConstants(m)), eta_(restitutionOf(m)),
      rockLevel_(k_.linear ? k_.alpha : std::tan(k_.alpha)), canSlide_(m.mu.has_value()),
      endT_(motion.end()), stopT_(m.duration.value_or(kInf)), hasDuration_(m.duration.has_value()) {
    absTol_ = BlockState(o.relTol * k_.alpha, o.relTol * k_.p * k_.alpha, o.relTol * k_.radius,
                         o.relTol * k_.p * k_.radius);
    h_ = 0.05 / k_.p;
    if (m.initialTilt > 0.0) {
        y_[0] = m.initialTilt * k_.alpha;
        mode_ = BlockMode::Rock;
        r_.rocked = true;
    }
}

void Run::countEvent() {
    if (++r_.events > o_.limits.maxEvents)
        throw RockingLimitError("rocking run: more than " + std::to_string(o_.limits.maxEvents) +
                                " events by t = " + std::to_string(t_) + " s");
}

void Run::record(double t, const BlockState& y) {
    if (o_.recorder) o_.recorder({t, y[0], y[1], y[2], mode_});
}

// The samples of the interval (t0, t1] on the recorder's grid, each from the step's start.
void Run::recordUpTo(double t0, const BlockState& y0, const BlockState& f0, double t1) {
    if (!o_.recorder) return;
    while (nextSample_ <= t1) {
        if (nextSample_ > t0) record(nextSample_, stepTo(t0, y0, f0, nextSample_ - t0));
        nextSample_ += o_.sampleInterval;
    }
}

BlockState Run::stepTo(double t0, const BlockState& y0, const BlockState& f0, double s) const {
    if (s <= 0.0) return y0;
    auto rhs = [this](double t, const BlockState& y) { return derivative(t, y); };
    return dop853Step<4>(rhs, t0, y0, f0, s).y;
}

double Run::eventValue(Event e, double t, const BlockState& y, const BlockState& f,
                       double* slope) const {
    *slope = 0.0;
    switch (e) {
    case Event::Impact:
        *slope = z_ * f[0];
        return z_ * y[0];
    case Event::Overturn:
        *slope = -z_ * f[0];
        return kHalfPi - z_ * y[0];
    case Event::Apex:
        *slope = z_ * f[1];
        return z_ * y[1];
    case Event::SlideStop: {
        const double dir = mode_ == BlockMode::SlideRock ? sigma_ * z_ : sigma_;
        *slope = dir * f[3];
        return dir * y[3];
    }
    case Event::Normal: {
        const BaseAccel a = baseAt(t);
        if (mode_ == BlockMode::Slide) return 1.0 + a.v;
        if (mode_ == BlockMode::SlideRock) return slideRockNormal(k_, z_, sigma_, y, a);
        return rockingContact(k_, z_, y[0], y[1], f[1], a).normal;
    }
    case Event::Friction: {
        const ContactForce c = rockingContact(k_, z_, y[0], y[1], f[1], baseAt(t));
        return k_.mu * c.normal - std::abs(c.friction);
    }
    case Event::None:
        break;
    }
    return 1.0;
}

// The root of an event function on the step from t0 by re-stepping: each trial time s is one
// DOP853 step from t0 of length s, so the event is as exact as a step. Safeguarded Newton from
// the Hermite guess; functions without a cheap slope are bisected.
double Run::locate(Event e, double t0, const BlockState& y0, const BlockState& f0, double h,
                   double g0, double s0, double g1, double s1) {
    auto fdf = [&](double s, double& v, double& dv) {
        const BlockState y = stepTo(t0, y0, f0, s);
        v = eventValue(e, t0 + s, y, derivative(t0 + s, y), &dv);
    };
    double lo = 0.0;
    if (g0 == 0.0) {
        // The step starts on the event's zero (a corner just lifted, an impact just passed):
        // the root sought is the next one, after the function has left zero. Halve towards the
        // start until it is positive; if it never is, the start is the root.
        double s = 0.5 * h, v = 0.0, dv = 0.0;
        for (int i = 0; i < 60; ++i, s *= 0.5) {
            fdf(s, v, dv);
            if (v > 0.0) break;
            if (v < 0.0) h = s, g1 = v, s1 = dv;
        }
        if (!(v > 0.0)) return 0.0;
        lo = s, g0 = v, s0 = dv;
    }
    const double guess = (s0 != 0.0 && s1 != 0.0) ? hermiteRootGuess(lo, h, g0, g1, s0, s1)
                                                  : std::numeric_limits<double>::quiet_NaN();
    const double tol = 4.0 * std::numeric_limits<double>::epsilon() * std::max(t0 + h, 1.0 / k_.p);
    const RootResult r = safeguardedNewton(fdf, lo, h, g0, g1, 200, guess, tol);
    return std::isfinite(r.x) ? std::clamp(r.x, lo, h) : h;
}

bool Run::locateAndApply(double t0, const BlockState& y0, const BlockState& f0, double h,
                         const BlockState& y1, const BlockState& f1) {
    Event events[4];
    int n = 0;
    if (mode_ == BlockMode::Slide) {
        events[n++] = Event::SlideStop;
        if (motion_.hasVertical()) events[n++] = Event::Normal;
    } else {
        events[n++] = Event::Impact;
        events[n++] = Event::Overturn;
        // Once overturning is decided the block is followed about its corner to |theta| =
        // pi/2 for the time; a corner lifting on the way does not change that it falls.
        if (!overturned_) events[n++] = Event::Normal;
        if (mode_ == BlockMode::SlideRock)
            events[n++] = Event::SlideStop;
        else if (canSlide_)
            events[n++] = Event::Friction;
    }
    Event first = Event::None;
    double sFirst = kInf;
    for (int i = 0; i < n; ++i) {
        double s0 = 0, s1 = 0;
        const double g0 = eventValue(events[i], t0, y0, f0, &s0);
        const double g1 = eventValue(events[i], t0 + h, y1, f1, &s1);
        if (!(g0 >= 0.0 && g1 < 0.0)) continue;
        const double s = locate(events[i], t0, y0, f0, h, g0, s0, g1, s1);
        if (s < sFirst) first = events[i], sFirst = s;
    }
    // The apex before the event (or in the step): the largest |theta| of this excursion.
    if (mode_ != BlockMode::Slide) {
        const double sEnd = first == Event::None ? h : sFirst;
        const BlockState yEnd = first == Event::None ? y1 : stepTo(t0, y0, f0, sEnd);
        const BlockState fEnd = first == Event::None ? f1 : derivative(t0 + sEnd, yEnd);
        double s0 = 0, s1 = 0;
        const double g0 = eventValue(Event::Apex, t0, y0, f0, &s0);
        const double g1 = eventValue(Event::Apex, t0 + sEnd, yEnd, fEnd, &s1);
        if (g0 >= 0.0 && g1 < 0.0 && sEnd > 0.0)
            seeTheta(stepTo(t0, y0, f0, locate(Event::Apex, t0, y0, f0, sEnd, g0, s0, g1, s1))[0]);
    }
    if (first == Event::None) return false;
    const BlockState ye = stepTo(t0, y0, f0, sFirst);
    recordUpTo(t0, y0, f0, t0 + sFirst);
    t_ = t0 + sFirst;
    y_ = ye;
    seeTheta(y_[0]);
    r_.maxSliding = std::max(r_.maxSliding, std::abs(y_[2]));
    apply(first);
    return true;
}

bool Run::apply(Event e) {
    countEvent();
    switch (e) {
    case Event::Overturn:
        overturned_ = stop_ = true;
        r_.overturnTime = t_;
        return false;
    case Event::Normal:
        left_ = stop_ = true;
        r_.leavesBaseTime = t_;
        return false;
    case Event::Impact:
        return afterImpact();
    case Event::Friction: {
        const BlockState f = derivative(t_, y_);
        sigma_ = -sgn(rockingContact(k_, z_, y_[0], y_[1], f[1], baseAt(t_)).friction);
        y_[3] = 0.0;
        return startMode(BlockMode::SlideRock);
    }
    case Event::SlideStop: {
        y_[3] = 0.0;
        const BaseAccel a = baseAt(t_);
        if (mode_ == BlockMode::Slide) {
            if (std::abs(a.h) <= k_.mu * (1.0 + a.v)) return startMode(BlockMode::Rest);
            sigma_ = -sgn(a.h);
            return startMode(BlockMode::Slide);
        }
        return startMode(BlockMode::Rock); // startMode sends it on sliding if friction fails
    }
    case Event::Apex:
    case Event::None:
        break;
    }
    return true;
}

// After an impact: is the rebound so small that the block is back at rest? Pulled back to its
// base with theta'' (the other corner's equation at theta = 0), a rebound theta' rises
// theta'^2 / (2 |theta''|), and the heights of all the bounces that follow sum to that over
// (1 - eta^2).
bool Run::reboundDies() const {
    const double w = std::abs(y_[1]);
    if (w < kRestRebound * k_.p * k_.alpha) return true;
    const double acc = z_ * rockingAcceleration(k_, z_, 0.0, baseAt(t_));
    if (!(acc < 0.0) || !(eta_ < 1.0)) return false;
    return w * w / (-2.0 * acc) / (1.0 - eta_ * eta_) < kRestHeight * k_.alpha;
}

// theta = 0: the block lands on its base and rocks on about the other corner with its angular
// velocity times eta (Housner 1963); the corner's sliding, if any, goes on.
bool Run::afterImpact() {
    r_.impactTimes.push_back(t_);
    y_[0] = 0.0;
    y_[1] *= eta_;
    z_ = -z_;
    if (t_ >= endT_) ++impactsAfterEnd_;
    if (!hasDuration_ && impactsAfterEnd_ >= kImpactsAfterEnd) stop_ = true;
    if (reboundDies()) {
        y_[1] = 0.0;
        if (y_[3] != 0.0) {
            sigma_ = sgn(y_[3]);
            return startMode(BlockMode::Slide);
        }
        return startMode(BlockMode::Rest);
    }
    if (mode_ == BlockMode::SlideRock && y_[3] != 0.0) {
        sigma_ = sgn(z_ * y_[3]);
        return startMode(BlockMode::SlideRock);
    }
    return startMode(BlockMode::Rock);
}

// Enter a mode and check at once what its start may already break: a block sliding with
// mu > tan alpha tips over its leading corner; a rocking corner whose friction does not hold
// slides; a normal force not positive leaves the base.
bool Run::startMode(BlockMode mode) {
    for (int pass = 0; pass < 4; ++pass) {
        mode_ = mode;
        const BaseAccel a = baseAt(t_);
        if (mode == BlockMode::Rest) {
            y_[0] = y_[1] = y_[3] = 0.0;
            break;
        }
        if (mode == BlockMode::Slide) {
            r_.slid = true;
            y_[0] = y_[1] = 0.0;
            if (k_.mu > std::tan(k_.alpha) && y_[3] != 0.0) {
                z_ = sgn(y_[3]);
                sigma_ = 1.0;
                mode = BlockMode::SlideRock;
                continue;
            }
            break;
        }
        const BlockState f = derivative(t_, y_);
        if (mode == BlockMode::SlideRock) {
            r_.slideRocked = r_.slid = r_.rocked = true;
            if (!overturned_ && !(slideRockNormal(k_, z_, sigma_, y_, a) > 0.0))
                return apply(Event::Normal);
            break;
        }
        r_.rocked = true;
        const ContactForce c = rockingContact(k_, z_, y_[0], y_[1], f[1], a);
        if (!overturned_ && !(c.normal > 0.0)) return apply(Event::Normal);
        if (canSlide_ && std::abs(c.friction) > k_.mu * c.normal) {
            sigma_ = -sgn(c.friction);
            mode = BlockMode::SlideRock;
            continue;
        }
        break;
    }
    record(t_, y_);
    return !stop_;
}

// After the base motion has ended, free rocking is decided by its energy (FreeRocking.h).
void Run::decideFree() {
    if (decided_ || t_ < endT_ || mode_ != BlockMode::Rock || canSlide_) return;
    decided_ = true;
    const FreeFate fate =
        freeFate(k_.linear ? RockingEquations::Linearised : RockingEquations::Exact, k_.p, k_.alpha,
                 eta_, y_[0], y_[1]);
    if (fate.overturns) {
        overturned_ = true;
        if (o_.stopAtOverturnDecision) stop_ = true;
        return;
    }
    seeTheta(fate.maxAbsTheta);
    if (o_.stopAtOverturnDecision && !hasDuration_) stop_ = true;
}

void Run::accept(double t1, const BlockState& y1) {
    t_ = t1;
    y_ = y1;
    seeTheta(y_[0]);
    r_.maxSliding = std::max(r_.maxSliding, std::abs(y_[2]));
}

// After the base motion has ended a block sliding flat decelerates at mu g (it cannot tip: it
// slides flat only with mu <= tan alpha): its stop is closed form, however small mu.
bool Run::finishSliding() {
    const double v = y_[3], decel = k_.mu * kStandardGravity;
    const double stopAt = t_ + std::abs(v) / decel;
    const double t1 = std::min(stopAt, stopT_), dt = t1 - t_;
    const double u1 = y_[2] + v * dt - 0.5 * sgn(v) * decel * dt * dt;
    if (o_.recorder)
        for (; nextSample_ <= t1; nextSample_ += o_.sampleInterval)
            if (nextSample_ > t_) {
                const double s = nextSample_ - t_;
                record(nextSample_,
                       BlockState(0.0, 0.0, y_[2] + v * s - 0.5 * sgn(v) * decel * s * s,
                                  v - sgn(v) * decel * s));
            }
    y_[2] = u1;
    y_[3] = t1 < stopAt ? v - sgn(v) * decel * dt : 0.0;
    t_ = t1;
    r_.maxSliding = std::max(r_.maxSliding, std::abs(u1));
    if (t1 == stopAt) {
        countEvent();
        startMode(BlockMode::Rest);
    }
    stop_ = true;
    return false;
}

// One DOP853 step (or its rejection) inside the current piece of the base motion.
bool Run::integrate() {
    decideFree();
    if (stop_) return false;
    if (mode_ == BlockMode::Slide && t_ >= endT_) return finishSliding();
    double pe = std::min(motion_.pieceEnd(t_), stopT_);
    if (t_ < endT_) pe = std::min(pe, endT_);
    const double wanted = std::min(h_, 0.5 / k_.p);
    const double h = std::min(wanted, pe - t_);
    if (++r_.steps > o_.limits.maxSteps)
        throw RockingLimitError("rocking run: more than " + std::to_string(o_.limits.maxSteps) +
                                " steps by t = " + std::to_string(t_) + " s");
    if (t_ > std::max(endT_, 0.0) + o_.limits.maxFreeTime)
        throw RockingLimitError("rocking run: still moving " +
                                std::to_string(o_.limits.maxFreeTime) +
                                " s after the base motion ended");
    const BlockState f0 = derivative(t_, y_);
    auto rhs = [this](double t, const BlockState& y) { return derivative(t, y); };
    const Dop853Result<4> step = dop853Step<4>(rhs, t_, y_, f0, h);
    const double err = dop853ErrorNorm<4>(step, y_, absTol_, o_.relTol);
    if (!(err <= 1.0)) {
        h_ = dop853RetryStep(h, err);
        return true;
    }
    h_ = std::max(h * dop853StepFactor(err), h < wanted ? wanted : 0.0);
    const double t0 = t_;
    const BlockState y0 = y_;
    if (locateAndApply(t0, y0, f0, h, step.y, step.f)) return !stop_;
    recordUpTo(t0, y0, f0, h == pe - t0 ? pe : t0 + h);
    accept(h == pe - t0 ? pe : t0 + h, step.y);
    return true;
}

double firstNormalLoss(const BaseMotion& m, double t0, double t1) {
    auto n = [&](double t) { return 1.0 + m.vertical(t); };
    if (!(n(t0) > 0.0)) return t0;
    if (n(t1) > 0.0) return kInf;
    double lo = t0, hi = t1;
    for (int i = 0; i < 200 && hi - lo > 4.0 * std::numeric_limits<double>::epsilon() * hi; ++i) {
        const double mid = 0.5 * (lo + hi);
        (n(mid) > 0.0 ? lo : hi) = mid;
    }
    return hi;
}

// At rest the block waits, piece by piece of the base motion, for the first instant the base
// lifts a corner (|a_h| > tan alpha (1 + a_v), linearised alpha) or, when mu is below that,
// makes it slide (|a_h| > mu (1 + a_v); Shenton 1996), or gravity's net pull vanishes.
bool Run::restPhase() {
    const bool slideFirst = canSlide_ && k_.mu < rockLevel_;
    const double level = slideFirst ? k_.mu : rockLevel_;
    while (t_ < endT_ && t_ < stopT_) {
        if (++r_.steps > o_.limits.maxSteps)
            throw RockingLimitError("rocking run: more than " + std::to_string(o_.limits.maxSteps) +
                                    " steps at rest");
        const double pe = std::min({motion_.pieceEnd(t_), endT_, stopT_});
        const double up = motion_.firstExceedance(+1, level, t_, pe);
        const double down = motion_.firstExceedance(-1, level, t_, pe);
        const double lift = motion_.hasVertical() ? firstNormalLoss(motion_, t_, pe) : kInf;
        const double te =
            std::min({std::isnan(up) ? kInf : up, std::isnan(down) ? kInf : down, lift});
        if (te == kInf) {
            recordUpTo(t_, y_, BlockState::Zero(), pe);
            t_ = pe;
            continue;
        }
        recordUpTo(t_, y_, BlockState::Zero(), te);
        t_ = te;
        countEvent();
        if (te == lift) return apply(Event::Normal);
        const double a = motion_.horizontal(te);
        if (slideFirst) {
            sigma_ = -sgn(a);
            return startMode(BlockMode::Slide);
        }
        z_ = -sgn(a); // a base pushed towards -x tips the block towards +x
        return startMode(BlockMode::Rock);
    }
    stop_ = true;
    return false;
}

RockingResult Run::go() {
    record(0.0, y_);
    if (mode_ == BlockMode::Rock) startMode(BlockMode::Rock);
    while (!stop_ && t_ < stopT_) {
        if (mode_ == BlockMode::Rest) {
            if (!restPhase()) break;
        } else if (!integrate()) {
            break;
        }
    }
    r_.endTime = t_;
    r_.slidingDisplacement = y_[2];
    if (overturned_)
        r_.outcome = RockingOutcome::Overturns;
    else if (left_)
        r_.outcome = RockingOutcome::LeavesBase;
    else if (r_.slideRocked || (r_.rocked && r_.slid))
        r_.outcome = RockingOutcome::SlideRock;
    else if (r_.rocked)
        r_.outcome = RockingOutcome::Rocks;
    else if (r_.slid)
        r_.outcome = RockingOutcome::Slides;
    else
        r_.outcome = RockingOutcome::Rest;
    return r_;
}

} // namespace

RockingResult simulateRocking(const RockingModel& model, const BaseMotion& motion,
                              const RockingRunOptions& options) {
    if (auto p = checkRockingModel(model); !p.empty()) throw std::invalid_argument(describe(p));
    return Run(model, motion, options).go();
}

} // namespace kinstab
