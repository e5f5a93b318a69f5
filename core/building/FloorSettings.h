// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The inputs of the floor-motion check that are not the building's or a code's: where the slab
// sits, how the storey stiffness is distributed, the modal damping, the ASCE 7-22 overstrength
// factor that enters R_mu and the EC8 element period. A project stores them under "floors".

#include <optional>
#include <string>

namespace kinstab {

// How storey stiffness varies up the building (storey i joins level i-1 to level i).
enum class StiffnessProfile {
    Uniform, // k_i = k
    Weight,  // k_i proportional to the weight carried, sum of w_j for j >= i
};
std::string stiffnessName(StiffnessProfile s); // "uniform" | "weight"
std::optional<StiffnessProfile> stiffnessFromName(const std::string& s);

struct FloorSettings {
    std::optional<int> slabLevel; // 1 = first level above the ground; none: the roof
    StiffnessProfile stiffness = StiffnessProfile::Uniform;
    double damping = 0.05;                  // modal damping ratio, every mode
    double omega0 = 2.5;                    // ASCE 7-22 overstrength factor Omega_0 (Table 12.2-1)
    std::optional<double> ec8ElementPeriod; // s, T_a of EN 1998-1 eq. 4.25; none: rigid element
};

// Empty when fine, else "floors.FIELD = VALUE: ..." (stories: the building's level count).
std::string validateFloorSettings(const FloorSettings& s, int stories);

} // namespace kinstab
