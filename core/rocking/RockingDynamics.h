// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The equations of motion of a free-standing block in each mode, and the contact forces at its
// base, as pure functions (docs/theory.md §10; sign convention in
// RockingSolver.h). The state is y = (theta, theta', u, u') with u the base or pivot corner's
// displacement relative to the base (m); the accelerations are in rad/s^2 and m/s^2.
//
// On a corner z = +-1 the block is described in its corner's frame (x mirrored when z = -1):
// there theta_z = z theta >= 0, a_z = z a_h, u_z = z u. With s = sin(alpha - theta_z),
// c = cos(alpha - theta_z), g' = g (1 + a_v), the centre of mass relative to the corner is
// R (-s, c), and the base's force on the block at the corner is (F, N) (per unit mass):
//   F = g a_z + u_z'' + R c theta_z'' + R s theta_z'^2
//   N = g' + R s theta_z'' - R c theta_z'^2
//   (R^2/3) theta_z'' = -R (s N + c F)            (moments about the centre of mass).
// Rocking (u_z'' = 0) gives theta_z'' = -p^2 (1 + a_v) [s + a_z c / (1 + a_v)] (Zhang & Makris
// 2001 eq. 12); slide-rock (F = -mu sigma N, sigma the corner's sliding direction in the frame)
// gives N = (g' - R c theta_z'^2) / (1 + 3 s (s - mu sigma c)),
//       theta_z'' = -(3/R) N (s - mu sigma c), u_z'' = -mu sigma N - g a_z - R c theta_z''
//       - R s theta_z'^2 (Shenton & Jones 1991; Zhang & Makris 2001 eqs. 21-23 in this frame).

#include "core/numerics/Dopri5.h"
#include "core/rocking/RockingModel.h"
#include "core/rocking/RockingResult.h"

namespace kinstab {

using BlockState = OdeVec<4>; // theta, theta', u, u'

struct BlockConstants {
    double alpha = 0, p = 0, radius = 0;
    bool linear = false;
    double mu = 0; // 0: no sliding
};
BlockConstants blockConstants(const RockingModel& m);

// The base's acceleration at an instant, g.
struct BaseAccel {
    double h = 0; // a_h
    double v = 0; // a_v
};

// theta'' of pure rocking on corner z.
double rockingAcceleration(const BlockConstants& k, double z, double theta, BaseAccel a);

// The base's force per unit mass on the corner z while the block rocks with theta'', in the
// corner's frame (F along its +x), m/s^2. Linearised equations: to their order,
// F = g a_z + R theta_z'' and N = g (1 + a_v) (the terms R s theta'' and R c theta'^2 are of
// second order in alpha and theta), so a linearised block leaves its base only with the base
// falling faster than gravity, as the literature's linear analyses assume.
struct ContactForce {
    double friction = 0; // F
    double normal = 0;   // N
};
ContactForce rockingContact(const BlockConstants& k, double z, double theta, double omega,
                            double thetaAccel, BaseAccel a);

// The derivative of the state in a mode. z: the corner (rocking modes); sigma: the sliding
// direction (+-1), global for Slide, in the corner's frame for SlideRock.
BlockState blockDerivative(const BlockConstants& k, BlockMode mode, double z, double sigma,
                           const BlockState& y, BaseAccel a);

// N of slide-rock on corner z, m/s^2.
double slideRockNormal(const BlockConstants& k, double z, double sigma, const BlockState& y,
                       BaseAccel a);

} // namespace kinstab
