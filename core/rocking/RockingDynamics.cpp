// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/rocking/RockingDynamics.h"

#include "core/base/PhysicalConstants.h"

#include <cmath>

namespace kinstab {

namespace {
constexpr double g = kStandardGravity;
}

BlockConstants blockConstants(const RockingModel& m) {
    BlockConstants k;
    k.alpha = blockAlpha(m.block);
    k.p = blockFrequency(m.block);
    k.radius = blockRadius(m.block);
    k.linear = m.equations == RockingEquations::Linearised;
    k.mu = m.mu.value_or(0.0);
    return k;
}

double rockingAcceleration(const BlockConstants& k, double z, double theta, BaseAccel a) {
    const double d = k.alpha * z - theta;
    const double gp = 1.0 + a.v;
    if (k.linear) return -k.p * k.p * (gp * d + a.h);
    return -k.p * k.p * (gp * std::sin(d) + a.h * std::cos(d));
}

ContactForce rockingContact(const BlockConstants& k, double z, double theta, double omega,
                            double thetaAccel, BaseAccel a) {
    ContactForce f;
    if (k.linear) {
        // To the first order of the linearised equation: the rotation's own terms R s theta''
        // and R theta'^2 are of second order in (alpha, theta), so N is gravity's.
        f.friction = g * z * a.h + k.radius * z * thetaAccel;
        f.normal = g * (1.0 + a.v);
        return f;
    }
    const double d = k.alpha - z * theta;
    const double s = std::sin(d), c = std::cos(d);
    const double tz = z * thetaAccel, wz = z * omega;
    f.friction = g * z * a.h + k.radius * (c * tz + s * wz * wz);
    f.normal = g * (1.0 + a.v) + k.radius * (s * tz - c * wz * wz);
    return f;
}

double slideRockNormal(const BlockConstants& k, double z, double sigma, const BlockState& y,
                       BaseAccel a) {
    const double d = k.alpha - z * y[0];
    const double s = std::sin(d), c = std::cos(d), wz = z * y[1];
    return (g * (1.0 + a.v) - k.radius * c * wz * wz) / (1.0 + 3.0 * s * (s - k.mu * sigma * c));
}

namespace {
BlockState slideRockDerivative(const BlockConstants& k, double z, double sigma, const BlockState& y,
                               BaseAccel a) {
    const double d = k.alpha - z * y[0];
    const double s = std::sin(d), c = std::cos(d), wz = z * y[1];
    const double q = s - k.mu * sigma * c;
    const double n = (g * (1.0 + a.v) - k.radius * c * wz * wz) / (1.0 + 3.0 * s * q);
    const double tz = -3.0 / k.radius * n * q;
    const double uz = -k.mu * sigma * n - g * z * a.h - k.radius * (c * tz + s * wz * wz);
    return BlockState(y[1], z * tz, y[3], z * uz);
}
} // namespace

BlockState blockDerivative(const BlockConstants& k, BlockMode mode, double z, double sigma,
                           const BlockState& y, BaseAccel a) {
    switch (mode) {
    case BlockMode::Rest:
        return BlockState::Zero();
    case BlockMode::Slide:
        return BlockState(0.0, 0.0, y[3], -g * (a.h + sigma * k.mu * (1.0 + a.v)));
    case BlockMode::Rock:
        return BlockState(y[1], rockingAcceleration(k, z, y[0], a), 0.0, 0.0);
    case BlockMode::SlideRock:
        return slideRockDerivative(k, z, sigma, y, a);
    }
    return BlockState::Zero();
}

} // namespace kinstab
