// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The slab's own inputs, declared once (core/base/NumberInput.h): the validators in core/slab,
// the project and study readers, the command line, Python and the slab and model panels read
// these, so no front end accepts what a run refuses or words a refusal differently.
//
// The lower bounds are physical and keep every accepted value finishing in bounded time:
// smaller values are no slab on a wall, and the solvers' event searches work at the edge of the
// double range there (a t* of 1e-160 underflows t*², a μ of 1e-20 asks for slips of 1e-20 g).

#include "core/base/InputLimits.h"
#include "core/base/NumberInput.h"
#include "core/excitation/EnvelopedSine.h"

namespace kinstab {

// Coulomb μ: tests of masonry joints give 0.55-0.66 (Furgerson 1980, ch. III); the slipperiest
// bearing, PTFE on polished steel, about 0.03. Below 0.01 no friction holds a slab, above ten is
// no friction coefficient.
inline constexpr NumberInput kMuInput{"mu", "", {0.01, 10.0}, 0.6, "friction coefficient"};
// Bearing over half the wall width: a thousandth of it is no bearing, a million a typing slip.
inline constexpr NumberInput kLimitInput{
    "limit", "", {1e-3, 1e6}, 1.0, "bearing limit (bearing / half the wall width)"};
// t*, the amplitude and the frequency are the enveloped sine's (core/excitation/EnvelopedSine.h).
// Wall width d, inches (t* from it, Furgerson 1980, eq. 4.3): a hundredth of an inch is a
// sheet, a thousand inches (25 m) no wall. No default: t* has one.
inline constexpr NumberInput kWallWidthInput{
    "wall_width_in", "in", {0.01, limits::kMaxWallWidthIn}, 8.0, "wall width"};
// The same wall in millimetres (the command line's --wall-width-mm): 0.254 mm to 25.4 m.
inline constexpr NumberInput kWallWidthMmInput{
    "wall_width_mm", "mm", {0.254, limits::kMaxWallWidthIn * 25.4}, 203.2, "wall width"};
// τ_out, the end of the run in units of t*: a million is a day at the paper's t*.
inline constexpr NumberInput kDurationInput{
    "duration", "", {0.0, 1e6, true}, 0.0, "run length tau_out"};
// Steps per period of the paper's RK4 solver (Furgerson 1980, Appendix: 16).
inline constexpr NumberInput kPaperStepsInput{
    "paper_steps", "", {4.0, 1e6}, 16.0, "RK4 steps per period"};
// Planar model: Θ = 2 wall length / wall width, the along-wall limit in half-widths.
inline constexpr NumberInput kThetaInput{
    "theta", "", {1e-3, 1e6}, 20.0, "along-wall limit (2 wall length / wall width)"};
// A_y / A_x: a ratio of 100 is a motion along the walls alone.
inline constexpr NumberInput kAyRatioInput{"ay_ratio", "", {0.0, 100.0}, 0.9, "A_y / A_x"};
// Frequency along the walls, Hz (core/excitation/FrequencyRange.h gives the reasons).
inline constexpr NumberInput kFyInput{
    "fy", "Hz", {kMinFrequencyHz, kMaxFrequencyHz}, 1.0, "frequency along the walls"};

} // namespace kinstab
