// SPDX-License-Identifier: GPL-3.0-or-later
// The approach of a stop in the log-radius variable s = ln|u| (docs/theory.md §6.5), where the
// direction and time are smooth; the stop time is where s -> -inf. A test on the dot product of
// velocities would fire early (the direction swings by up to 180 degrees in the last instants,
// F7).
#include "core/slab/PlanarRun.h"

#include <algorithm>
#include <cmath>

namespace kinstab::planar {

double PlanarRun::dissipationRate(double tau, double ex, double ey) {
    const Vec2 a = m_.accel(tau);
    return mu_ * m_.normal(tau) + a.x * ex + a.y * ey;
}

// Log-radius form: with u = e^s (cos th, sin th), D = mu n + a.e,
//   dth/ds = (a.e_perp)/D,  dtau/ds = -e^s/D,  d delta/ds = e^s e dtau/ds.
// Smooth as s -> -inf wherever D > 0 (where |u| decreases).
Vec5 PlanarRun::rhsS(double s, const Vec5& z) {
    ++r_.slab.work.accelEvaluations;
    const double tau = z[2] + t_;
    const double norm = norm2(z[0], z[1]);
    const double ex = z[0] / norm, ey = z[1] / norm;
    const Vec2 a = m_.accel(tau);
    const double d = mu_ * m_.normal(tau) + a.x * ex + a.y * ey;
    const double turn = (-a.x * ey + a.y * ex) / d;
    const double rho = std::exp(s);
    const double dtau = -rho / d;
    Vec5 f;
    f << -turn * ey, turn * ex, dtau, rho * ex * dtau, rho * ey * dtau;
    return f;
}

// Approach of a stop in s = ln|u|, from the current state (|u| > 0, |u| decreasing).
PlanarRun::Approach PlanarRun::approachStop(double end) {
    LogState l = enterLog();
    Vec5 absTol;
    absTol << o_.relTol, o_.relTol, o_.relTol, o_.absTol, o_.absTol;
    auto f = [&](double ss, const Vec5& zz) { return rhsS(ss, zz); };
    double ds = -1.0;
    while (true) {
        if (l.s <= l.sFloor) return stopAtFloor(l);
        const double h = std::max(ds, l.sFloor - l.s);
        if (++r_.slab.work.steps > o_.maxSteps) {
            fail("step limit reached");
            return Approach::Done;
        }
        const auto st = dop853Step<5, 0, 3>(f, l.s, l.z, l.fz, h);
        const double err = dop853ErrorNorm<5>(st, l.z, absTol, o_.relTol);
        const double tauNew = l.tEntry + st.y[2];
        // a_h and n at the step's end, asked once for D there and the turn test below.
        const Vec2 aNew = m_.accel(tauNew);
        const double nNew = m_.normal(tauNew);
        const double dNew = mu_ * nNew + aNew.x * (st.y[0] / norm2(st.y[0], st.y[1])) +
                            aNew.y * (st.y[1] / norm2(st.y[0], st.y[1]));
        if (!(err <= 1.0) || !(dNew > 0.0) || !(st.y[2] >= l.z[2])) {
            ++r_.slab.work.restarts;
            ds = h * kLogShrink;
            // |u| turns before reaching 0: back to time as the variable.
            if (std::abs(ds) < kMinLogStep)
                return leaveLog(l.tEntry + l.z[2], fromLog(l.z, l.s), std::exp(l.s), 0.0);
            continue;
        }
        const StateEvent pieceEnd{StateKind::PieceEnd, Direction::Rising, 2, 1.0, end, l.tEntry};
        if (pieceEnd.fired(pieceEnd.value(st.y[2]))) return logPieceEnd(l, h, st.y, end);
        if (const StateEvent* wall = firstFired(walls_, fromLog(st.y, l.s + h)))
            return logCollapse(l, h, st.y, *wall);
        l.s += h;
        l.z = st.y;
        const double nrm = norm2(l.z[0], l.z[1]);
        l.z[0] /= nrm;
        l.z[1] /= nrm;
        l.fz = f(l.s, l.z);
        ds = h * dop853StepFactor(err);
        const Vec4 y = fromLog(l.z, l.s);
        if (isSlaved(tauNew, y)) {
            moveTo(tauNew, y);
            return Approach::Exited;
        }
        // The speed is about to turn (D -> 0): leave s before dtau/ds blows up.
        if (dNew < kTurnRatio * (mu_ * nNew + norm2(aNew.x, aNew.y)))
            return leaveLog(tauNew, y, std::exp(l.s), norm2(aNew.x, aNew.y));
    }
}

// The current state in s = ln|u|: (direction, time since entry, displacement).
PlanarRun::LogState PlanarRun::enterLog() {
    LogState l;
    l.tEntry = t_;
    const double rho = norm2(y_[2], y_[3]);
    l.s = std::log(rho);
    l.sFloor = std::log(kStopFloor * std::max(slipPeak_, rho));
    l.z << y_[2] / rho, y_[3] / rho, 0.0, y_[0], y_[1];
    l.fz = rhsS(l.s, l.z);
    return l;
}

// The state in tau of z at s.
Vec4 PlanarRun::fromLog(const Vec5& z, double s) const {
    Vec4 y;
    const double r = std::exp(s), nrm = norm2(z[0], z[1]);
    y << z[3], z[4], r * z[0] / nrm, r * z[1] / nrm;
    return y;
}

// The step from l's start to sTarget, re-taken: the step's dense output.
Vec5 PlanarRun::logRestep(const LogState& l, double sTarget) {
    return dop853Step<5, 0, 3>([&](double ss, const Vec5& zz) { return rhsS(ss, zz); }, l.s, l.z,
                               l.fz, sTarget - l.s)
        .y;
}

// Stopped: the rest of the way is |u| / D at slope -D (F7 (c)).
PlanarRun::Approach PlanarRun::stopAtFloor(const LogState& l) {
    const double tau = l.tEntry + l.z[2];
    const double d = dissipationRate(tau, l.z[0], l.z[1]);
    Vec4 y = fromLog(l.z, l.s);
    y[2] = y[3] = 0.0;
    moveTo(tau + std::exp(l.s) / std::max(d, kRateFloor), y);
    return Approach::Stopped;
}

// Back to tau at (tau, y), at the given speed, with a first step of kReentryStep times the time
// the speed takes to change at rate mu n + accel.
PlanarRun::Approach PlanarRun::leaveLog(double tau, const Vec4& y, double speed, double accel) {
    moveTo(tau, y);
    hNext_ = kReentryStep * speed / (mu_ * m_.normal(t_) + accel + kRateFloor);
    return Approach::Exited;
}

// The piece ends before the stop, inside the step of length h in s: find s with tau(s) = end on
// the step's dense output and go back to time.
PlanarRun::Approach PlanarRun::logPieceEnd(const LogState& l, double h, const Vec5& zEnd,
                                           double end) {
    const StateEvent e{StateKind::PieceEnd, Direction::Rising, 2, 1.0, end, l.tEntry};
    const double sEnd = locateEvent(
        e,
        [&](double ss, double& yk, double& dyk) {
            const Vec5 zz = logRestep(l, ss);
            yk = zz[2];
            dyk = rhsS(ss, zz)[2];
        },
        l.s + h, l.s, e.value(zEnd[2]), e.value(l.z[2]), r_.slab.work.rootIterations);
    const Vec5 zz = logRestep(l, sEnd);
    moveTo(end, fromLog(zz, sEnd));
    hNext_ = kReentryStep * std::exp(sEnd) / (mu_ * m_.normal(end) + kRateFloor);
    return Approach::ReachedEnd;
}

// A wall's edge passed inside the step of length h in s: located on the step's dense output.
PlanarRun::Approach PlanarRun::logCollapse(const LogState& l, double h, const Vec5& zEnd,
                                           const StateEvent& wall) {
    const StateEvent e = wall.shifted(3); // dx, dy are z[3], z[4]
    const int k = e.component;
    const double sc = locateEvent(
        e,
        [&](double ss, double& yk, double& dyk) {
            const Vec5 zz = logRestep(l, ss);
            yk = zz[k];
            dyk = rhsS(ss, zz)[k];
        },
        l.s + h, l.s, e.value(zEnd[k]), e.value(l.z[k]), r_.slab.work.rootIterations);
    const Vec5 zz = logRestep(l, sc);
    collapse(l.tEntry + zz[2], fromLog(zz, sc), wall);
    return Approach::Done;
}

// At a stop: stick if |a_h| <= mu n, else slide on at once along -a_h (a reversal).
PlanarRun::Step PlanarRun::afterStop() {
    y_[2] = y_[3] = 0.0;
    if (m_.onsetMargin(t_) > 0.0) {
        ++r_.slab.slipIntervals;
        slipPeak_ = 0.0;
        return event(EventKind::Reversal) ? Step::Continue : Step::Done;
    }
    slipping_ = false;
    return event(EventKind::Stick) ? Step::Continue : Step::Done;
}

} // namespace kinstab::planar
