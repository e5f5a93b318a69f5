// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The free-standing block's results as `kinstab-cli rocking` and `rocking-map` write them
// (docs/user-guide.md "The command line"): the block and its model, one run's result, what drove
// it, the overturning search and the overturning map. Absent values are null.

#include "core/excitation/Envelope.h"
#include "core/records/Accelerogram.h"
#include "core/rocking/OverturningAmplitude.h"
#include "core/rocking/OverturningMap.h"
#include "core/rocking/Pulse.h"
#include "core/rocking/RockingModel.h"
#include "core/rocking/RockingResult.h"

#include <nlohmann/json.hpp>

#include <optional>

namespace kinstab {

// half_width_m, half_height_m, alpha_rad, radius_m, p_rad_s, restitution (and its source),
// equations, initial_tilt, mu, duration_s.
nlohmann::json rockingModelJson(const RockingModel& m);
// outcome, max_theta_over_alpha, impact_times_s, overturn_time_s, sliding_displacement_m, ...
nlohmann::json rockingResultJson(const RockingResult& r);

// The "excitation" object: kind "pulse" (shape, amplitude_g, frequency_hz or duration_s),
// "enveloped-sine" (amplitude_g, frequency_hz, the envelope's α and β, end_s) or "record" (the
// accelerogram's keys, scaled_peak_g, the building's level that filtered it, the vertical
// record).
nlohmann::json pulseExcitationJson(const Pulse& p);
nlohmann::json sineExcitationJson(const Envelope& env, double amplitude, double frequency,
                                  double endS);
nlohmann::json recordExcitationJson(const Accelerogram& motion, double scaledPeak,
                                    std::optional<int> level, const Accelerogram* vertical);

// The overturning search (rocking --critical): critical_amplitude_g, overturning_intervals_g,
// the search's settings, critical_runs, critical_run_limit_reached.
nlohmann::json overturningSearchJson(const OverturningIntervals& iv, const OverturningSearch& s);
// shape, a_p_over_alpha_g, omega_p_over_p, state_legend, state and max_theta_over_alpha (a row
// per frequency), complete.
nlohmann::json overturningMapJson(const OverturningMap& m);

} // namespace kinstab
