// SPDX-License-Identifier: GPL-3.0-or-later
// The stepping of a rocking run (core/rocking/RockingSolver.h): DOP853 steps in a moving mode,
// the rest phases between the base's exceedances, and the closed-form end of sliding after the
// base motion; the run's entry point.
#include "core/base/PhysicalConstants.h"
#include "core/numerics/Dop853.h"
#include "core/rocking/RockingRun.h"

#include <stdexcept>
#include <string>

namespace kinstab::blockrun {

RockingRun::RockingRun(const RockingModel& m, const BaseMotion& motion, const RockingRunOptions& o)
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

void RockingRun::countEvent() {
    if (++r_.events > o_.limits.maxEvents)
        throw RockingLimitError("rocking run: more than " + std::to_string(o_.limits.maxEvents) +
                                " events by t = " + std::to_string(t_) + " s");
}

void RockingRun::record(double t, const BlockState& y) {
    if (o_.recorder) o_.recorder({t, y[0], y[1], y[2], mode_});
}

// The samples of the interval (t0, t1] on the recorder's grid, each from the step's start.
void RockingRun::recordUpTo(double t0, const BlockState& y0, const BlockState& f0, double t1) {
    if (!o_.recorder) return;
    while (nextSample_ <= t1) {
        if (nextSample_ > t0) record(nextSample_, stepTo(t0, y0, f0, nextSample_ - t0));
        nextSample_ += o_.sampleInterval;
    }
}

BlockState RockingRun::stepTo(double t0, const BlockState& y0, const BlockState& f0,
                              double s) const {
    if (s <= 0.0) return y0;
    auto rhs = [this](double t, const BlockState& y) { return derivative(t, y); };
    return dop853Step<4>(rhs, t0, y0, f0, s).y;
}

void RockingRun::accept(double t1, const BlockState& y1) {
    t_ = t1;
    y_ = y1;
    seeTheta(y_[0]);
    r_.maxSliding = std::max(r_.maxSliding, std::abs(y_[2]));
}

// After the base motion has ended a block sliding flat decelerates at mu g (it cannot tip: it
// slides flat only with mu <= tan alpha): its stop is closed form, however small mu.
bool RockingRun::finishSliding() {
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
bool RockingRun::integrate() {
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

namespace {

// The first instant in [t0, t1] the base falls at g or faster (1 + a_v <= 0), by bisection;
// infinity when it does not.
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

} // namespace

// At rest the block waits, piece by piece of the base motion, for the first instant the base
// lifts a corner (|a_h| > tan alpha (1 + a_v), linearised alpha) or, when mu is below that,
// makes it slide (|a_h| > mu (1 + a_v); Shenton 1996), or gravity's net pull vanishes.
bool RockingRun::restPhase() {
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

RockingResult RockingRun::go() {
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

} // namespace kinstab::blockrun

namespace kinstab {

RockingResult simulateRocking(const RockingModel& model, const BaseMotion& motion,
                              const RockingRunOptions& options) {
    if (auto p = checkRockingModel(model); !p.empty()) throw std::invalid_argument(describe(p));
    return blockrun::RockingRun(model, motion, options).go();
}

} // namespace kinstab
