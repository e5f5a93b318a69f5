// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// EN 1998-1:2004 §4.3.5.2: the seismic coefficient of a secondary element (appendage) at
// height z of a building of height H,
//   S_a = alpha S [3 (1 + z/H) / (1 + (1 - T_a/T_1)^2) - 0.5] >= alpha S      (eq. 4.25)
// with alpha = a_g / g (a_g = gamma_I a_gR, ground type A), S the soil factor, T_a the
// element's fundamental period and T_1 the building's. For a rigid element (T_a = 0) it is
// alpha S (1 + 1.5 z/H); with gamma_a = q_a = 1 (eq. 4.24) S_a is the peak floor acceleration.

#include "core/codes/Eurocode8.h"
#include "core/codes/FloorDemand.h"

#include <optional>

namespace kinstab {

// The bracket of eq. 4.25 (>= 1): S_a / (alpha S).
double ec8FloorFactor(double zOverH, double elementPeriod, double buildingPeriod);

// elementPeriod: none for a rigid element. slabLevel 1-based. Throws InputError.
FloorDemand ec8FloorDemand(const Building& b, const Eurocode8Inputs& in,
                           std::optional<double> elementPeriod, int slabLevel);

} // namespace kinstab
