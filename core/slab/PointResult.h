// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a surface keeps of one slab run at one (amplitude, frequency) point, and the function
// that computes it for a model. Each model's case (1-DOF, planar) makes its point function here,
// on the slab floor; the sweep (core/sweep/Sweep.h) runs any of them over a grid.

#include "core/slab/SlabTypes.h"

#include <functional>

namespace kinstab {

struct PointResult {
    Outcome outcome = Outcome::Failed;
    double tauC = 0;                    // NaN unless collapsed (or lifted off)
    ExitSide exitSide = ExitSide::None; // planar collapses: across or along the walls
};

// The point of the enveloped sine one run was taken at, and the τ_ref its γc is of: what each
// view of a single run (the GUI's picked points, Python's results) keeps beside the solver's
// result, for either model.
struct RunPoint {
    double amplitude = 0; // g
    double frequency = 0; // Hz
    double tauRef = 1;
};

using PointFunction = std::function<PointResult(double amplitude, double frequencyHz)>;

} // namespace kinstab
