// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The parts of core's analysis entry point (core/analysis/RunAnalysis.h) that the surface and
// critical subcommands print, for the 1-DOF and the planar model alike: the request names the
// model, these name the part.

#include "app/cli/Args.h"
#include "core/analysis/RunAnalysis.h"

#include <nlohmann/json.hpp>

namespace kinstab::cli {

// The model flags as core's request: the 1-DOF case (slab1DCaseFromFlags), and with
// --model planar the planar inputs on that same case (planarCaseFromFlags). Throws UsageError.
AnalysisRequest modelRequestFromFlags(const Args& args);
// The request's model in a result's keys: the planar case's (planarCaseJson), or the 1-DOF
// slab's model, solver, envelope, mu and t*.
nlohmann::json modelKeysJson(const AnalysisRequest& request);

// The γc surface of the request's model over grid.
SweepResult surfaceOf(AnalysisRequest request, const SweepGrid& grid, int threads);
// A_crit at the request's criticalFrequencies: a number per frequency, null where nothing
// collapses up to the search limit.
nlohmann::json criticalCurveJson(AnalysisRequest request);

} // namespace kinstab::cli
