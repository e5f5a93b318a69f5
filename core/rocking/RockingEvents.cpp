// SPDX-License-Identifier: GPL-3.0-or-later
// The events of a rocking run (the table of core/rocking/BlockEvents.h): their functions, their
// location on a step, and the mode transitions they make.
#include "core/numerics/Dop853.h"
#include "core/numerics/RootFinding.h"
#include "core/rocking/RockingRun.h"

namespace kinstab::blockrun {

double RockingRun::eventValue(Event e, double t, const BlockState& y, const BlockState& f,
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

bool RockingRun::watches(Guard g) const {
    switch (g) {
    case Guard::Vertical:
        return motion_.hasVertical();
    case Guard::NotOverturned:
        return !overturned_;
    case Guard::CanSlide:
        return canSlide_;
    case Guard::Always:
        break;
    }
    return true;
}

// The root of an event function on the step from t0 by re-stepping: each trial time s is one
// DOP853 step from t0 of length s, so the event is as exact as a step. Safeguarded Newton from
// the Hermite guess; functions without a cheap slope are bisected.
double RockingRun::locate(Event e, double t0, const BlockState& y0, const BlockState& f0, double h,
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

// The apex before the first event (or in the step): the largest |theta| of this excursion.
void RockingRun::seeApex(double t0, const BlockState& y0, const BlockState& f0, double h,
                         const BlockState& y1, const BlockState& f1, Event first, double sFirst) {
    const double sEnd = first == Event::None ? h : sFirst;
    const BlockState yEnd = first == Event::None ? y1 : stepTo(t0, y0, f0, sEnd);
    const BlockState fEnd = first == Event::None ? f1 : derivative(t0 + sEnd, yEnd);
    double s0 = 0, s1 = 0;
    const double g0 = eventValue(Event::Apex, t0, y0, f0, &s0);
    const double g1 = eventValue(Event::Apex, t0 + sEnd, yEnd, fEnd, &s1);
    if (g0 >= 0.0 && g1 < 0.0 && sEnd > 0.0)
        seeTheta(stepTo(t0, y0, f0, locate(Event::Apex, t0, y0, f0, sEnd, g0, s0, g1, s1))[0]);
}

// Every event the mode watches, located on the step; the earliest (ties: the earlier row) is
// applied at its time.
bool RockingRun::locateAndApply(double t0, const BlockState& y0, const BlockState& f0, double h,
                                const BlockState& y1, const BlockState& f1) {
    Event first = Event::None;
    double sFirst = kInf;
    for (const WatchedEvent& w : watchedEvents(mode_)) {
        if (!watches(w.guard)) continue;
        double s0 = 0, s1 = 0;
        const double g0 = eventValue(w.event, t0, y0, f0, &s0);
        const double g1 = eventValue(w.event, t0 + h, y1, f1, &s1);
        if (!(g0 >= 0.0 && g1 < 0.0)) continue;
        const double s = locate(w.event, t0, y0, f0, h, g0, s0, g1, s1);
        if (s < sFirst) first = w.event, sFirst = s;
    }
    if (mode_ != BlockMode::Slide) seeApex(t0, y0, f0, h, y1, f1, first, sFirst);
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

bool RockingRun::apply(Event e) {
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

// Enter a mode and check at once what its start may already break: a block sliding with
// mu > tan alpha tips over its leading corner; a rocking corner whose friction does not hold
// slides; a normal force not positive leaves the base.
bool RockingRun::startMode(BlockMode mode) {
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

} // namespace kinstab::blockrun
