// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The planar slab's state at any tau from the solver's recorded path (every accepted step and
// every event): cubic Hermite interpolation of the displacement with the velocities at both
// ends, as accurate as the solver's own dense output between steps.

#include "core/slab/History.h"
#include "core/slab/PlanarSolver.h"

#include <vector>

namespace kinstab::ui {

// delta and velocity across the walls (x), or along them (y) when alongWalls; state is the sign
// of the velocity while slipping, else 0. Before the path: at rest; after it: its last point.
HistorySample planarStateAt(const std::vector<PlanarSample>& path, double tau,
                            bool alongWalls = false);

} // namespace kinstab::ui
