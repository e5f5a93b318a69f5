// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/assessment/RunAssessment.h"

#include "core/analysis/RunAnalysis.h"
#include "core/assessment/ProjectRequest.h"
#include "core/base/InputError.h"
#include "core/codes/CodeSet.h"
#include "core/io/Project.h"

#include <cmath>
#include <stdexcept>

namespace kinstab {

namespace {

// The floor analysis without the per-level searches, then the search of the slab's level alone.
std::optional<FloorCheckParts> slabLevelFloors(const Project& p, const Accelerogram& ground,
                                               AnalysisControl& control) {
    FloorAnalysisInput in = floorAnalysisInput(p, ground);
    in.critical = false;
    const FloorAnalysis a = analyseFloors(in, &control.sweepControl());
    if (a.demands.empty()) return std::nullopt;
    const auto at = static_cast<std::size_t>(a.slabLevel - 1);
    std::vector<LevelCritical> c =
        levelCriticalPga(p.slab, {a.motions[at]}, a.pga, p.critical, &control.sweepControl());
    if (c.empty() || control.isCancelled()) return std::nullopt;
    FloorCheckParts f;
    f.demands = a.demands;
    f.atSlab = c.front();
    f.atSlab.level = a.slabLevel;
    f.pga = a.pga;
    f.stories = p.building.stories;
    return f;
}

} // namespace

FloorAnalysisInput floorAnalysisInput(const Project& p, const Accelerogram& ground) {
    FloorAnalysisInput in;
    in.building = p.building;
    in.codes = p.codes;
    in.settings = p.floors.value_or(FloorSettings{});
    in.slab = p.slab;
    in.search = p.critical;
    in.ground = ground;
    return in;
}

std::optional<FloorCheckParts> floorCheckParts(const FloorAnalysis& a, int stories) {
    const auto at = static_cast<std::size_t>(a.slabLevel - 1);
    if (a.cancelled || a.demands.empty() || at >= a.critical.size()) return std::nullopt;
    FloorCheckParts f;
    f.demands = a.demands;
    f.atSlab = a.critical[at];
    f.pga = a.pga;
    f.stories = stories;
    return f;
}

AssessmentRun runAssessment(const Project& p, const std::optional<PlanarCase>& planar,
                            AnalysisControl& control) {
    AssessmentRun run;
    // First: a bad results or hazard file is an InputError before minutes of searches.
    run.parts.risk = projectRiskParts(p);
    AnalysisParts sineParts;
    sineParts.designCheck = true;
    run.request = analysisRequest(p, sineParts, planar);
    const AnalysisRequest& sine = run.request;
    const AnalysisResult s = runAnalysis(sine, control);
    if (s.checkError) std::rethrow_exception(s.checkError);
    run.parts.sine = s.check;
    if (p.record) {
        AnalysisRequest rec = sine; // the record check runs the 1-DOF slab
        rec.planar.reset();
        rec.parts = AnalysisParts{};
        rec.parts.recordCheck = true;
        run.record = runAnalysis(rec, control).record;
        if (run.record) {
            run.parts.record = run.record->verdicts;
            run.parts.recordName = run.record->ground.name;
            if (p.floors) run.parts.floors = slabLevelFloors(p, run.record->ground, control);
            if (!p.blocks.empty())
                run.parts.blocks = blockCheckParts(p, run.record->ground, &control.sweepControl());
        }
    }
    run.cancelled = control.isCancelled();
    if (!run.cancelled) run.assessment = composeAssessment(p, run.parts);
    return run;
}

} // namespace kinstab
