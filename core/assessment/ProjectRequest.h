// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one place a project becomes an analysis request (core/analysis/AnalysisRequest.h): its
// model, grid, codes, A_crit search and record, with the parts asked for. kinstab-cli check (and
// Python's assess, through runAssessment), the design report and the GUI's Run all start here and
// change only what is their own (the GUI's curve search, the report's overlay frequencies).

#include "core/analysis/AnalysisRequest.h"
#include "core/io/Project.h"

#include <optional>

namespace kinstab {

// The project's request: the 1-DOF case, and for a planar project its planar inputs with the
// vertical motion read by core (core/slab/VerticalRecord.h; throws InputError naming the field);
// the grid; A_crit at the grid's frequencies; the codes computed from the building; the
// project's search for the curve and the checks; its record.
AnalysisRequest analysisRequest(const Project& p, const AnalysisParts& parts);

// The same with the planar case given (its vertical motion read by the caller, as Python reads
// it from files); required when the project's model is planar, ignored otherwise.
AnalysisRequest analysisRequest(const Project& p, const AnalysisParts& parts,
                                const std::optional<PlanarCase>& planar);

} // namespace kinstab
