// SPDX-License-Identifier: GPL-3.0-or-later
// Slaved slip (docs/theory.md §6.5): while |u| is small the direction of u relaxes to its slow
// manifold at rate |a|/|u|, far faster than anything else moves, and an explicit method would
// crawl at steps of about |u| / |a| (stability, not accuracy). On the manifold u lags -a_h by
//   phi = -theta_a' |u| / (|a| + m),  m = |a_h| - mu n  (theta_a: the direction of a_h),
// exact while the coefficients are frozen (|u| then grows or shrinks linearly and phi with it);
// the neglected terms are O((Omega |u| / |a|)^2) relative. The reduced state (|u|, dx, dy) is
// smooth: |u|' = |a| cos phi - mu n, delta' = |u| (-a_h / |a|) rotated by phi. It is integrated
// by the same DOP853 with steps set by the tolerance, not by |u|.
#include "core/slab/PlanarRun.h"

#include <algorithm>
#include <cmath>

namespace kinstab::planar {

namespace {
// The stop of a slaved slip: |u| (state component 0) falls to 0.
constexpr StateEvent kSlavedStop{StateKind::Stop, Direction::Falling, 0, 1.0, 0.0, 0.0};

// cos and sin of the manifold's angle phi, which is O(|u|): below kSmallAngle the series to
// phi^4 and phi^5 leave out less than phi^6 / 720 < 2e-21 (relative, far below rounding), where
// libm's sincos had been 3 % of the planar solver's instructions.
constexpr double kSmallAngle = 1e-3;
void cosSin(double phi, double& c, double& s) {
    if (!(std::abs(phi) < kSmallAngle)) {
        c = std::cos(phi);
        s = std::sin(phi);
        return;
    }
    const double p2 = phi * phi;
    c = 1.0 - p2 * (0.5 - p2 / 24.0);
    s = phi * (1.0 - p2 * (1.0 / 6.0 - p2 / 120.0));
}
} // namespace

Vec3 PlanarRun::rhsSlaved(double tau, const Vec3& z) {
    ++r_.slab.work.accelEvaluations;
    const Vec2 a = m_.accel(tau);
    const double n = m_.normal(tau);
    const Vec2 dir = slavedDirection(a, m_.accelSlope(tau), n, z[0]);
    const double speedRate = -mu_ * n - (a.x * dir.x + a.y * dir.y);
    Vec3 f;
    f << speedRate, z[0] * dir.x, z[0] * dir.y;
    return f;
}

// The unit direction of u on the slow manifold at speed rho (-a_h / |a| turned by phi), from a_h,
// its slope and n at one time.
Vec2 PlanarRun::slavedDirection(const Vec2& a, const Vec2& sl, double n, double rho) const {
    const double am = norm2(a.x, a.y);
    if (!(am > 0.0)) return {0.0, 0.0};
    const double turn = (a.x * sl.y - a.y * sl.x) / (am * am); // theta_a'
    const double relax = 2.0 * am - mu_ * n;                   // |a| + m
    const double phi = -turn * rho / std::max(relax, kAttraction * am);
    double c = 1.0, sn = 0.0;
    cosSin(phi, c, sn);
    const double ex = -a.x / am, ey = -a.y / am;
    return {ex * c - ey * sn, ex * sn + ey * c};
}

PlanarRun::Step PlanarRun::slaved(double end) {
    const double rhoExit = kSlavedExit * slavedSpeed_;
    Vec3 z;
    z << norm2(y_[2], y_[3]), y_[0], y_[1];
    auto f = [&](double t, const Vec3& zz) { return rhsSlaved(t, zz); };
    Vec3 absTol = Vec3::Constant(o_.absTol);
    absTol[0] = kSlavedSpeedTol * o_.absTol;
    Vec3 f0 = f(t_, z);
    double h = startLength_;
    while (t_ < end) {
        // On a piece between onset roots the sign of |u|' is fixed: |u| has no interior zero.
        const double t0 = t_, pieceEnd = std::min(end, nextCut(t0)),
                     hh = std::min(h, pieceEnd - t0);
        if (++r_.slab.work.steps > o_.maxSteps) return fail("step limit reached");
        const auto st = dop853Step<3, 0, 1>(f, t0, z, f0, hh);
        const double err = dop853ErrorNorm<3>(st, z, absTol, o_.relTol);
        if (!(err <= 1.0)) {
            ++r_.slab.work.restarts;
            h = dop853RetryStep(hh, err);
            if (h < kStepUnderflow * std::max(1.0, t0))
                return fail("step size underflow in a slaved slip");
            continue;
        }
        if (kSlavedStop.fired(kSlavedStop.value(st.y[0]))) return slavedStop(t0, hh, z, f0, st.y);
        const bool truncated = hh < h;
        const double grow = hh * dop853StepFactor(err);
        h = truncated ? std::max(h, grow) : grow;
        z = st.y;
        f0 = st.f;
        if (leaveSlaved(t0 + hh, z, rhoExit)) break;
    }
    return Step::Continue;
}

// The speed reaches zero in the step of length hh from (t0, z): a stop, located on the step's
// dense output (the step re-taken to each trial time).
PlanarRun::Step PlanarRun::slavedStop(double t0, double hh, const Vec3& z, const Vec3& f0,
                                      const Vec3& zEnd) {
    auto f = [&](double t, const Vec3& zz) { return rhsSlaved(t, zz); };
    const double ts = z[0] <= 0.0
                          ? t0
                          : locateEvent(
                                kSlavedStop,
                                [&](double t, double& yk, double& dyk) {
                                    const Vec3 zz = dop853Step<3, 0, 1>(f, t0, z, f0, t - t0).y;
                                    yk = zz[0];
                                    dyk = f(t, zz)[0];
                                },
                                t0, t0 + hh, kSlavedStop.value(z[0]), kSlavedStop.value(zEnd[0]),
                                r_.slab.work.rootIterations);
    const Vec3 zs = ts == t0 ? z : Vec3(dop853Step<3, 0, 1>(f, t0, z, f0, ts - t0).y);
    Vec4 y;
    y << zs[1], zs[2], 0.0, 0.0;
    moveTo(ts, y);
    return afterStop();
}

// The slaved state z accepted at t1, in the full variables; true when the slip is fast enough
// to go back to the full equations (their first step must resolve the relaxation).
bool PlanarRun::leaveSlaved(double t1, const Vec3& z, double rhoExit) {
    const Vec2 a1 = m_.accel(t1);
    const Vec2 dir = slavedDirection(a1, m_.accelSlope(t1), m_.normal(t1), z[0]);
    Vec4 y;
    y << z[1], z[2], z[0] * dir.x, z[0] * dir.y;
    moveTo(t1, y);
    if (!(z[0] > rhoExit)) return false;
    hNext_ = kRelaxStep * z[0] / std::max(norm2(a1.x, a1.y), kRateFloor);
    return true;
}

// True when |u| is small, the manifold attracts and u lies on it within kSlavedAngle, so that
// the slip is slaved.
bool PlanarRun::isSlaved(double tau, const Vec4& y) const {
    return norm2(y[2], y[3]) <= slavedSpeed_ && onManifold(tau, y, kSlavedAngle);
}

// True when the manifold attracts (|a| + m >= kAttraction |a|) and u lies on it within `angle`.
bool PlanarRun::onManifold(double tau, const Vec4& y, double angle) const {
    const double rho = norm2(y[2], y[3]);
    if (rho == 0.0) return true;
    const Vec2 a = m_.accel(tau);
    const double am = norm2(a.x, a.y);
    const double n = m_.normal(tau);
    if (!(am > 0.0) || 2.0 * am - mu_ * n < kAttraction * am) return false;
    const Vec2 dir = slavedDirection(a, m_.accelSlope(tau), n, rho);
    return std::abs(dir.x * y[3] - dir.y * y[2]) <= angle * rho &&
           dir.x * y[2] + dir.y * y[3] > 0.0;
}

} // namespace kinstab::planar
