// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/slab/MoreauSolver2D.h"

#include <cmath>

namespace kinstab {

namespace {

// Moreau's catching-up step for the slip velocity: w = u - h a, projected onto the friction
// disc's complement (the slab stops when |w| <= h mu n). Returns the part of w kept: 0 is stuck.
double projectVelocity(double& ux, double& uy, const Vec2& a, double n, double h, double mu) {
    const double wx = ux - h * a.x, wy = uy - h * a.y;
    const double w = std::hypot(wx, wy);
    const double keep = w > 0.0 ? std::max(0.0, 1.0 - h * mu * n / w) : 0.0;
    ux = wx * keep;
    uy = wy * keep;
    return keep;
}

// The step from (dx, dy) to (nx, ny), starting at tau0, left the slab's bearing: where by
// linear interpolation inside the step for each side; the earlier one wins.
void collapseInStep(PlanarResult& r, const PlanarParams& p, double tau0, double h, const Vec2& d,
                    const Vec2& next) {
    const double dx = d.x, dy = d.y, nx = next.x, ny = next.y;
    const double fx = (std::abs(nx) - p.limit), fy = (std::abs(ny) - p.theta);
    const double sx = fx > 0.0 ? (p.limit - std::abs(dx)) / (std::abs(nx) - std::abs(dx)) : 2.0;
    const double sy = fy > 0.0 ? (p.theta - std::abs(dy)) / (std::abs(ny) - std::abs(dy)) : 2.0;
    r.slab.outcome = Outcome::Collapsed;
    r.exitSide = sx <= sy ? ExitSide::Across : ExitSide::Along;
    r.slab.tauC = tau0 + std::min(sx, sy) * h;
    r.slab.tauEnd = r.slab.tauC;
    r.slab.maxAbsDelta = std::max(r.slab.maxAbsDelta, std::abs(nx));
    r.maxAbsDeltaY = std::max(r.maxAbsDeltaY, std::abs(ny));
}

} // namespace

PlanarResult solveMoreau2D(const SlabModel2D& m, double h, double tauMax) {
    PlanarResult r;
    const PlanarParams& p = m.params();
    double dx = 0, dy = 0, ux = 0, uy = 0;
    const long steps = static_cast<long>(std::ceil(tauMax / h));
    bool slipping = false;
    for (long k = 0; k < steps; ++k) {
        const double t1 = static_cast<double>(k + 1) * h; // no drift from summing h
        const Vec2 a = m.accel(t1);
        const double n = m.normal(t1);
        r.slab.work.accelEvaluations += 1;
        ++r.slab.work.steps;
        if (n <= 0.0) {
            r.slab.outcome = Outcome::LiftOff;
            r.slab.tauC = r.tauLiftOff = t1;
            r.slab.tauEnd = t1;
            return r;
        }
        const bool nowSlipping = projectVelocity(ux, uy, a, n, h, p.mu) > 0.0;
        if (nowSlipping && !slipping) ++r.slab.slipIntervals;
        slipping = nowSlipping;
        const double nx = dx + h * ux, ny = dy + h * uy;
        const double fx = (std::abs(nx) - p.limit), fy = (std::abs(ny) - p.theta);
        if (fx > 0.0 || fy > 0.0) {
            collapseInStep(r, p, static_cast<double>(k) * h, h, {dx, dy}, {nx, ny});
            return r;
        }
        dx = nx;
        dy = ny;
        r.slab.maxAbsDelta = std::max(r.slab.maxAbsDelta, std::abs(dx));
        r.maxAbsDeltaY = std::max(r.maxAbsDeltaY, std::abs(dy));
        if (!slipping && m.quietAfter(t1)) {
            r.slab.outcome = Outcome::Stable;
            r.slab.tauEnd = t1;
            break;
        }
    }
    if (r.slab.outcome != Outcome::Stable) {
        r.slab.outcome = Outcome::Stable;
        r.slab.tauEnd = tauMax;
    }
    r.slab.residualDelta = dx;
    r.residualDeltaY = dy;
    return r;
}

} // namespace kinstab
