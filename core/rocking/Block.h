// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A free-standing rigid rectangular block (docs/theory.md §10): half-width b
// and half-height h, uniform, on a rigid base. Its slenderness alpha = atan(b/h), the distance
// R = sqrt(b^2 + h^2) from a base corner to the centre of mass, and its frequency parameter
// p = sqrt(3 g / (4 R)) (Housner 1963): the polar moment about a corner is (4/3) m R^2.

#include "core/base/NumberInput.h"

#include <string>

namespace kinstab {

struct Block {
    double halfWidth = 0.2;  // b, m
    double halfHeight = 0.6; // h, m
    bool operator==(const Block&) const = default;
};

double blockAlpha(const Block& b);     // atan(b/h), rad
double blockRadius(const Block& b);    // R = sqrt(b^2 + h^2), m
double blockFrequency(const Block& b); // p = sqrt(3 g / (4 R)), rad/s, g standard gravity
// Housner's coefficient of restitution on the angular velocity at impact, from conservation of
// angular momentum about the new pivot: 1 - 1.5 sin^2 alpha (Housner 1963).
double housnerRestitution(double alpha);
// The block of a given slenderness alpha (rad) and frequency parameter p (rad/s): R = 3g/(4p^2),
// b = R sin alpha, h = R cos alpha. How the papers state their blocks.
Block blockFromAlphaP(double alpha, double p);

// The inputs of a block and its model, declared once (core/base/NumberInput.h). A block from
// 1 mm (a die) to 100 m (a tower) each way; a restitution in (0, 1] (1: no loss at impact);
// a friction coefficient > 0 (up to 10, as the slab's); an initial tilt as a fraction of alpha
// in [0, 1) (1 would balance on the corner); a duration after which the run stops.
inline constexpr NumberInput kHalfWidthInput{
    "half_width", "m", {1e-3, 100.0}, 0.2, "half-width of the block"};
inline constexpr NumberInput kHalfHeightInput{
    "half_height", "m", {1e-3, 100.0}, 0.6, "half-height of the block"};
inline constexpr NumberInput kRestitutionInput{
    "restitution", "", {0.0, 1.0, true}, 1.0, "coefficient of restitution"};
inline constexpr NumberInput kBlockMuInput{
    "mu", "", {0.0, 10.0, true}, 0.6, "friction coefficient"};
inline constexpr NumberInput kInitialTiltInput{
    "initial_tilt", "", {0.0, 0.999999}, 0.0, "initial tilt theta0 / alpha"};
inline constexpr NumberInput kRockingDurationInput{
    "duration", "s", {0.0, 1e5, true}, 0.0, "duration"};

// The first input out of range, or nothing.
InputProblem checkBlock(const Block& b);

} // namespace kinstab
