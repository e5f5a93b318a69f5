// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Runs what a project's assessment needs, and only that: the codes, A_crit(1/T) of the project's
// model, the record's critical peak, the critical ground PGA of the slab's own level of the
// building model (not every level's, which only the report's floor figure shows), and the risk
// integral of each study set against the study's hazard curve (from the study's results; the
// study itself is not run here). Used by
// `kinstab-cli check` and Python's kinstab.assess; the report and the GUI compose the same
// assessment from the fuller analyses they run (composeAssessment).

#include "core/analysis/AnalysisControl.h"
#include "core/analysis/AnalysisRequest.h"
#include "core/assessment/Assessment.h"
#include "core/building/FloorAnalysis.h"
#include "core/check/RecordAnalysis.h"
#include "core/codes/CodeResult.h"
#include "core/slab/PlanarCase.h"

#include <optional>
#include <vector>

namespace kinstab {

struct AssessmentRun {
    AnalysisRequest request; // of the sine's check (core/assessment/ProjectRequest.h): its codes
    AssessmentParts parts;
    std::optional<RecordAnalysis> record; // the record's run, motion and critical peak
    Assessment assessment;
    bool cancelled = false; // then the assessment is empty
};

// planar: the project's planar case with its vertical motion read (the caller reads the record;
// core/slab/PlanarSettings.h), required when the project's model is planar. Throws InputError
// on a bad project input (also study results or a hazard curve that cannot be read, naming the
// field), RecordError on a record that cannot be read.
AssessmentRun runAssessment(const Project& p, const std::optional<PlanarCase>& planar,
                            AnalysisControl& control);

// The floor analysis a project asks for under a ground record: its building, codes, floor
// settings (defaults when none), slab case and search; every level searched.
FloorAnalysisInput floorAnalysisInput(const Project& p, const Accelerogram& ground);

// The floor check's parts from a floor analysis that searched every level (the report, the GUI).
std::optional<FloorCheckParts> floorCheckParts(const FloorAnalysis& a, int stories);

} // namespace kinstab
