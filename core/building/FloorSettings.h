// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The inputs of the floor-motion check that are not the building's or a code's: where the slab
// sits, how the storey stiffness is distributed, the modal damping, the ASCE 7-22 overstrength
// factor that enters R_mu and the EC8 element period. A project stores them under "floors".

#include "core/base/NumberInput.h"

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

// The floor check's own inputs, declared once: modal damping of buildings is 1-10 %; 0.99 is
// the last value that still oscillates measurably (the damped period grows without bound as
// the ratio nears 1).
inline constexpr NumberInput kModalDampingInput{
    "damping", "", {0.0, 0.99}, 0.05, "modal damping ratio (fraction of critical)"};
inline constexpr NumberInput kOmega0Input{
    "asce7_omega0", "", {1.0, 5.0}, 2.5, "overstrength factor Omega_0 (ASCE 7-22 Table 12.2-1)"};
inline constexpr NumberInput kEc8ElementPeriodInput{
    "ec8_element_period_s", "s", {0.0, 100.0}, 0.0, "element period T_a (EN 1998-1 eq. 4.25)"};

// The first setting out of range, named by its key (slab_level: 1 to stories, the building's
// level count), or nothing; validateFloorSettings says it as "floors.FIELD = VALUE: ...".
InputProblem checkFloorSettings(const FloorSettings& s, int stories);
std::string validateFloorSettings(const FloorSettings& s, int stories);

} // namespace kinstab
