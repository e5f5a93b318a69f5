// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The keys of what core's analysis entry point (core/analysis/RunAnalysis.h) was asked and found,
// as `kinstab-cli critical` and `check` write them (docs/user-guide.md "The command line").

#include "core/analysis/AnalysisRequest.h"
#include "core/analysis/CriticalCurve.h"
#include "core/sweep/CriticalAmplitude.h"

#include <nlohmann/json.hpp>

namespace kinstab {

// The request's model in a result's keys: the planar case's (planarCaseJson), or the 1-DOF
// slab's model, solver, envelope, mu and t*.
nlohmann::json requestModelJson(const AnalysisRequest& q);
// A critical-amplitude search's settings: max_amplitude, scan_step, tolerance.
nlohmann::json criticalSearchJson(const CriticalSearch& s);
// `kinstab-cli critical`: the model's keys, frequencies, a_crit (a number per frequency, null
// where nothing collapses up to the search limit) and the search's settings.
nlohmann::json criticalCurveJson(const AnalysisRequest& q, const CriticalCurve& c);

} // namespace kinstab
