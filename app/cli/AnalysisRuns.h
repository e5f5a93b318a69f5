// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The parts of core's analysis entry point (core/analysis/RunAnalysis.h) that the surface and
// critical subcommands print, for the 1-DOF and the planar model alike: the request names the
// model, these name the part.

#include "app/cli/Args.h"
#include "core/analysis/RunAnalysis.h"

namespace kinstab::cli {

// The model flags as core's request: the 1-DOF case (slab1DCaseFromFlags), and with
// --model planar the planar inputs on that same case (planarCaseFromFlags). Throws UsageError.
AnalysisRequest modelRequestFromFlags(const Args& args);

// The γc surface of the request's model over grid.
SweepResult surfaceOf(AnalysisRequest request, const SweepGrid& grid, int threads);
// A_crit at the request's criticalFrequencies (core/io/AnalysisJson.h writes it).
CriticalCurve criticalCurveOf(AnalysisRequest request);

} // namespace kinstab::cli
