// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Moreau's time-stepping for the planar slab (docs/theory.md §6.5): proximal implicit Euler on the
// differential inclusion u' in -mu n d|u| - a_h, with the closed-form step
//   w = u_k - h a_h(tau_{k+1}),  u_{k+1} = w max(0, 1 - h mu n(tau_{k+1}) / |w|),
//   delta_{k+1} = delta_k + h u_{k+1}.
// First order, no event location at all (sticking is exact), unconditionally stable: an
// independent check of the event-driven solver, not a production method.

#include "core/slab/PlanarSolver.h"

namespace kinstab {

// Fixed step h up to tauMax (or until the slab sticks for good). The collapse time is
// interpolated linearly inside the step that leaves the walls; lift-off ends the run.
PlanarResult solveMoreau2D(const SlabModel2D& model, double h, double tauMax);

// Richardson extrapolation of a first-order quantity from steps h and h/2.
inline double richardsonFirstOrder(double coarse, double fine) {
    return 2.0 * fine - coarse;
}

} // namespace kinstab
