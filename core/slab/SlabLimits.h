// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Ranges of the slab's own inputs, read by the validators in core/slab and by the slab and model
// panels, so a field never accepts what a run refuses.

#include "core/base/Range.h"

namespace kinstab {

// Coulomb μ: tests of masonry joints give 0.55-0.66 (Furgerson 1980, ch. III); ten is no
// friction coefficient.
inline constexpr Range kMuRange{0.0, 10.0};
// Bearing over half the wall width, and the planar model's along-wall limit Θ, in half-widths:
// a million is a typing slip.
inline constexpr Range kSlipLimitRange{0.0, 1e6, true};
// t* = √(d / 2g), s: 100 s is a wall 200 km wide.
inline constexpr Range kTstarRange{0.0, 100.0, true};
// A_y / A_x of the planar model: a ratio of 100 is a motion along the walls alone.
inline constexpr Range kAyRatioRange{0.0, 100.0};

} // namespace kinstab
