// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How a block is modelled in a run: the block, the impact, the equations and friction, where it
// starts and how long the run lasts (docs/theory.md §10).

#include "core/rocking/Block.h"

#include <optional>

namespace kinstab {

// Which equations of motion describe rocking.
enum class RockingEquations {
    Exact,     // theta'' = -p^2 [sin(alpha sgn theta - theta) + (a/g) cos(alpha sgn theta - theta)]
    Linearised // theta'' = p^2 [theta - alpha sgn theta - a/g]: slender blocks, the closed forms
};

struct RockingModel {
    Block block;
    // Coefficient of restitution on the angular velocity at an impact; none: Housner's
    // 1 - 1.5 sin^2 alpha.
    std::optional<double> restitution;
    RockingEquations equations = RockingEquations::Exact;
    // Coulomb friction at the base (static = kinetic); none: the base holds the block
    // horizontally, it never slides.
    std::optional<double> mu;
    // theta0 / alpha in [0, 1): the block is released from rest at theta0 = initialTilt alpha
    // (rotating about the corner at +x, the sign convention of RockingSolver.h).
    double initialTilt = 0.0;
    // s: the run ends here at the latest. None: it ends once the base motion has ended and the
    // block is at rest or overturned, or rocks freely without being able to overturn (then
    // followed to rest, or for 200 impacts when it never comes to rest: eta = 1); bounded by
    // RockingLimits.
    std::optional<double> duration;
};

// Bounds of one run; a run that reaches one throws RockingLimitError naming it.
struct RockingLimits {
    long maxSteps = 2'000'000; // integrator steps, accepted and rejected
    long maxEvents = 100'000;  // impacts, mode changes
    double maxFreeTime = 1e4;  // s of motion after the base motion has ended
};

// The restitution in use: the model's, or Housner's for its alpha.
double restitutionOf(const RockingModel& m);
// Empty when the model can be run, else "--flag value: why" style text naming the input (its
// NumberInput key).
InputProblem checkRockingModel(const RockingModel& m);

} // namespace kinstab
