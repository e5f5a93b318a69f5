// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Regularized friction, for comparison only (docs/theory.md §6.6 case 1, §6 baseline (c)): the sign
// of the slip velocity is smoothed to tanh(v / width),
//   delta'' = -mu tanh(delta' / width) - a(tau),
// and integrated with classical RK4 at a fixed step. It shows why regularization is the wrong
// tool here: the model has no sticking, so under |a| < mu the slab creeps at
// width * artanh(|a| / mu), and the equation is stiff (d f / d v = -mu / width at v = 0): RK4
// is stable only for steps below 2.785 width / mu, so the cost grows like 1 / width.

#include "core/excitation/Excitation1D.h"
#include "core/slab/SlabTypes.h"

namespace kinstab {

struct RegularizedSettings {
    double width = 1e-3; // epsilon, in units of the relative velocity
    double step = 0.0;   // RK4 step; 0: the stability-safe min(period / 32, width / mu)
    double period = 0.0; // period of the excitation, for the default step (0: ignore)
    double endTau = 0.0; // integrate to here (0: params.duration, else until |a| < mu for good)
    long maxSteps = 100'000'000;
};

// Outcome Collapsed (tau_c interpolated linearly in the step that crosses the limit) or Stable
// at the end; events are not located (the model has none), work.steps counts RK4 steps.
SlabResult solveRegularized(const Excitation1D& excitation, const SlabParams& params,
                            const RegularizedSettings& settings);

std::string validateRegularizedSettings(const RegularizedSettings& s); // empty when fine

} // namespace kinstab
