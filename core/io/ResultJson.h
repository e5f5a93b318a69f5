// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// JSON forms of results, with the keys of the command-line contract (docs/user-guide.md "The
// command line"). NaN never appears: a missing number is null.

#include "core/slab/SlabTypes.h"
#include "core/sweep/Sweep.h"

#include <nlohmann/json.hpp>

namespace kinstab {

nlohmann::json numberOrNull(double x);
nlohmann::json workJson(const SolverWork& w);
nlohmann::json eventsJson(const std::vector<SlabEvent>& events);
// outcome, tau_c, gamma_c, slip_intervals, max_abs_delta, residual_delta, work.
nlohmann::json slabResultJson(const SlabResult& r, double tauRef);
// amplitudes, frequencies, tau_c, gamma_c, outcome (docs/user-guide.md "The command line"
// "surface").
nlohmann::json sweepJson(const SweepResult& r, double tauRef);
std::string sweepCsv(const SweepResult& r, double tauRef);

} // namespace kinstab
