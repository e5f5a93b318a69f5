// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// ASCE/SEI 7-22 §13.3.1: the horizontal seismic design force on a nonstructural component,
//   F_p = 0.4 S_DS I_p W_p (H_f / R_mu) (C_AR / R_po),  0.3 S_DS I_p W_p <= F_p <= 1.6 S_DS I_p
//   W_p,
// read for a rigid element on the floor (C_AR = 1, R_po = 1, I_p = 1) as the peak floor
// acceleration 0.4 S_DS H_f / R_mu (g), with
//   H_f = 1 + a_1 (z/h) + a_2 (z/h)^10,  a_1 = 1/T_a <= 2.5,  a_2 = 1 - (0.4/T_a)^2 >= 0
//   (eq. 13.3-4), R_mu = (1.1 R / (I_e Omega_0))^(1/2) >= 1.3 (eq. 13.3-6),
// T_a the approximate period of §12.8.2.1. At the MCE_R level S_DS becomes S_MS = 1.5 S_DS
// (§11.4.5: S_DS = 2/3 S_MS).

#include "core/codes/Asce7_22.h"
#include "core/codes/FloorDemand.h"

namespace kinstab {

// H_f of eq. 13.3-4 at z/h for a building of approximate period ta (s).
double asce7HeightFactor(double zOverH, double ta);
// R_mu of eq. 13.3-6.
double asce7DuctilityFactor(double r, double importance, double omega0);

// slabLevel 1-based; mce: the MCE_R level instead of the design level. Throws InputError.
FloorDemand asce7FloorDemand(const Building& b, const Asce7Inputs& in, double omega0, int slabLevel,
                             bool mce);

} // namespace kinstab
