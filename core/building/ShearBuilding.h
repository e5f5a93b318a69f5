// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The building as a shear building: one horizontal degree of freedom per level (level n = the
// roof), level masses from the level weights, storeys as springs between levels. Storey i joins
// level i-1 (level 0 = the ground) to level i. The stiffness profile fixes the ratios of the
// storey stiffnesses; their common scale is chosen so that the first-mode period equals the
// building's period T. Masses are level weights over the mean level weight: with k scaled to
// T, the unit of mass drops out of every period, mode shape and floor acceleration.

#include "core/building/FloorSettings.h"
#include "core/codes/Building.h"

#include <Eigen/Dense>

#include <string>
#include <vector>

namespace kinstab {

struct ShearBuilding {
    std::vector<double> masses;    // per level, bottom first (relative: w_i / mean w)
    std::vector<double> heights;   // per level above the base, in the building's unit
    std::vector<double> stiffness; // per storey, bottom first, in mass units / s^2
    double period = 1.0;           // s, the first-mode period the stiffness is scaled to
    std::string periodSource;      // "entered" or "ASCE 7-22 T_a (no period entered)"
};

// Throws InputError on a bad building. The period is the building's entered T; without one,
// the ASCE 7-22 approximate period T_a (eq. 12.8-7), as said in periodSource.
ShearBuilding shearBuilding(const Building& b, StiffnessProfile profile);

// M = diag(m);  K tridiagonal: K_ii = k_i + k_{i+1} (k_{n+1} = 0), K_{i,i+1} = -k_{i+1}.
Eigen::MatrixXd massMatrix(const ShearBuilding& s);
Eigen::MatrixXd stiffnessMatrix(const ShearBuilding& s);

} // namespace kinstab
