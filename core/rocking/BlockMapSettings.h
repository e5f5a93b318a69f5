// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The GUI's "free-standing block" model: one block, its impact, equations and friction, and the
// overturning map asked of it (a pulse shape over a_p/(alpha g) and omega_p/p, Zhang & Makris
// 2001 figs. 7-9). A value type the project saves under "block_map" (core/io/BlockMapJson.h) so
// the choice and its inputs come back on open; the map itself is core's OverturningMap.

#include "core/rocking/OverturningMap.h"
#include "core/rocking/RockingModel.h"

#include <string>

namespace kinstab {

struct BlockMapSettings {
    bool selected = false;    // the GUI shows the block's map instead of the slab's surface
    Block block;              // b, h (m)
    std::optional<double> mu; // none: the base holds it, it never slides
    std::optional<double> restitution; // none: Housner's 1 - 1.5 sin^2 alpha
    RockingEquations equations = RockingEquations::Exact;
    PulseShape shape = PulseShape::OneSine;
    // The map's axes run from one step above 0 to these maxima in `points` equal steps
    // (a = amplitudeMax k / points, k = 1..points): no point sits on a_p = 0 or omega_p = 0.
    double amplitudeMax = 10.0; // a_p / (alpha g)
    double frequencyMax = 10.0; // omega_p / p
    int points = 101;
    bool operator==(const BlockMapSettings&) const = default;
};

// The map's inputs, declared once for the project reader and the GUI's fields.
inline constexpr NumberInput kMapAmplitudeMaxInput{
    "amplitude_max", "", {0.0, 1e4, true}, 10.0, "largest a_p/(alpha g) of the map"};
inline constexpr NumberInput kMapFrequencyMaxInput{
    "frequency_max", "", {0.0, 1e4, true}, 10.0, "largest omega_p/p of the map"};
inline constexpr NumberInput kMapPointsInput{
    "points", "", {2.0, 1025.0}, 101.0, "points per axis of the map"};

// The rocking model the map runs: from rest, until the fate is decided.
RockingModel blockMapModel(const BlockMapSettings& s);
// The same block with the other equations (linearised <-> exact): its boundary is drawn over
// the map so the two can be compared.
RockingModel otherEquationsModel(const BlockMapSettings& s);
// core's map spec for these settings (threads: all).
OverturningMapSpec blockMapSpec(const BlockMapSettings& s);

// The first input out of range, or nothing (block, mu, restitution, the map's axes).
InputProblem checkBlockMapSettings(const BlockMapSettings& s);

// "exact" | "linearised", as the project file writes them; nullopt for anything else.
std::string equationsName(RockingEquations e);
std::optional<RockingEquations> equationsFromName(const std::string& name);

} // namespace kinstab
