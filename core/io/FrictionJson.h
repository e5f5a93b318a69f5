// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// JSON form of a friction-law calibration (kinstab-cli friction, docs/theory.md §8;
// docs/user-guide.md "The command line"). Forces in kips, displacements in inches, pressures in
// psi; missing numbers are null.

#include "core/friction/FrictionCalibration.h"

#include <nlohmann/json.hpp>

namespace kinstab {

// V1, V_inf, c, b, beta, alpha, f_m, V_inf_upper_bound, at_upper_bound.
nlohmann::json decayFitJson(const DecayFit& fit);
nlohmann::json grubbsJson(const GrubbsResult& r);
nlohmann::json intervalsJson(const SampleIntervals& s);
// {"options": ..., "groups": [...], "configurations": [...]}.
nlohmann::json frictionCalibrationJson(const FrictionCalibration& cal);

} // namespace kinstab
