// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The planar model's run as `kinstab-cli simulate --model planar` writes it (docs/user-guide.md
// "The command line"): the 1-DOF result's keys, never renamed, with the planar keys added.

#include "core/slab/PlanarRecorder.h"
#include "core/slab/PlanarSolver.h"

#include <nlohmann/json.hpp>

#include <vector>

namespace kinstab {

// slabResultJson of r.slab, with exit_side ("across" | "along", null unless collapsed),
// tau_lift_off, max_abs_delta_y, residual_delta_y and work.rejected_steps.
nlohmann::json planarResultJson(const PlanarResult& r, double tauRef);
// --events: tau, kind, dx, dy, ux, uy of each event.
nlohmann::json planarEventsJson(const std::vector<PlanarEvent>& events);

} // namespace kinstab
