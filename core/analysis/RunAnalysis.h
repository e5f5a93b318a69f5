// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one entry point for the analysis a project asks for: the γc surface, A_crit(f), the
// design check of ch. V and the record's check, for the 1-DOF or the planar model. The GUI's
// Run, kinstab-cli (surface, critical, check) and the design report all call it. Every part runs
// on core's one thread pool (core/sweep/ParallelFor.h), in the order surface, curve, design
// check, record check.

#include "core/analysis/AnalysisControl.h"
#include "core/analysis/AnalysisRequest.h"
#include "core/analysis/AnalysisResult.h"

namespace kinstab {

// Steps of a request as AnalysisControl counts them.
std::size_t analysisSteps(const AnalysisRequest& request);

// Throws RecordError / std::invalid_argument from the record check and InternalError from an
// unsound run (requireSoundRuns); a failed design check is kept in checkError instead.
AnalysisResult runAnalysis(const AnalysisRequest& request, AnalysisControl& control);

} // namespace kinstab
