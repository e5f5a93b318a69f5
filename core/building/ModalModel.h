// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The undamped modes of a shear building, all of them, from K phi = omega^2 M phi (Eigen's
// generalized self-adjoint solver): periods, mode shapes and participation factors
// Gamma_r = phi_r' M 1 / phi_r' M phi_r, with sum_r Gamma_r phi_r = 1 (a rigid shift of the
// base is the sum of all modes). Chopra, "Dynamics of Structures", §13.1-13.2.

#include "core/building/ShearBuilding.h"

#include <vector>

namespace kinstab {

struct Mode {
    double period = 0;         // s
    double omega = 0;          // rad/s
    double participation = 0;  // Gamma_r
    double effectiveMass = 0;  // Gamma_r^2 phi_r' M phi_r / sum m: share of the total mass
    std::vector<double> shape; // phi_r per level, bottom first, roof component +1
};

struct ModalModel {
    std::vector<Mode> modes; // first (longest period) first
    std::vector<double> heights;
};

ModalModel modalModel(const ShearBuilding& s);

} // namespace kinstab
