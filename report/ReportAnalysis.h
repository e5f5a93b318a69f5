// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The analyses a design report shows, run from a project: the codes, the design check, the
// project's γc sweep, finer sweeps for the figures, A_crit(f), the slice at the building
// frequency and a solver cross-check for the numerics section. The GUI can fill the same
// struct from what it already computed; the CLI calls computeReportAnalysis.

#include "core/analysis/RunAnalysis.h"
#include "core/assessment/Assessment.h"
#include "core/building/FloorAnalysis.h"
#include "core/check/DesignCheck.h"
#include "core/check/RecordAnalysis.h"
#include "core/codes/CodeResult.h"
#include "core/io/Project.h"
#include "core/rocking/OverturningMap.h"
#include "core/slab/PlanarSolver.h"
#include "core/sweep/Sweep.h"
#include "report/FigureData.h"

#include <optional>
#include <vector>

namespace kinstab::report {

// The exact solver's τc checked against the paper's RK4 solver at H = T / paperSteps on the
// project grid (docs/theory.md §6.6): an estimate of the τc error, independent of the exact solver.
struct SolverCrossCheck {
    double paperSteps = 1024;
    std::size_t compared = 0;        // points where both collapsed
    std::size_t outcomeMismatch = 0; // points where one collapsed and the other did not
    double maxRelTauDiff = 0;        // max |τc,paper − τc,exact| / τc,exact
    double exactSeconds = 0;
    double paperSeconds = 0;
};

struct ReportAnalysis {
    std::vector<CodeResult> codes;
    DesignCheckResult check;
    double checkSeconds = 0;
    SweepResult projectSweep; // on the project's grid (the numbers tabled in the report)
    SurfaceData netSurface;   // fine grid over the project's range: the wireframe
    SurfaceData mapSurface;   // fine grid down to the code ratios: the contour map
    double figureSweepSeconds = 0;
    long figureRuns = 0;
    DesignOverlay overlay; // A_crit(f), code ratios, design frequency
    long critRuns = 0;
    SliceData slice;
    std::optional<SolverCrossCheck> crossCheck;
    // The planar model's integrator settings when the planar model ran (none: the 1-DOF slab).
    std::optional<PlanarOptions> planarSolver;
    // Where every A_crit scan started, below which nothing slips: μ for the 1-DOF slab, the
    // planar no-slip amplitude for the planar model.
    double scanFrom = 0;
    // The project's record, when it has one: single run, critical peak, its verdicts.
    std::optional<RecordAnalysis> record;
    std::optional<FloorAnalysis> floors; // when the project has "floors" and a record
    // The study's sets against its hazard curve, when the study has results and a hazard curve
    // (core/assessment/RiskCheck.h): the risk section and the risk checks.
    std::optional<RiskCheckParts> risk;
    // The project's free-standing blocks searched on their levels under the ground record
    // (core/assessment/BlockCheck.h): the blocks section and the block checks.
    std::optional<std::vector<BlockCheckPart>> blocks;
    std::vector<OverturningMap> blockMaps; // each block's one-sine map (BlocksSection.cpp)
    // Every check the project implies, composed once from the analyses above (assessReport):
    // page 1 and every section show it and compose no verdict of their own.
    Assessment assessment;
    double totalSeconds = 0;
};

struct AnalysisOptions {
    int figureGrid = 41; // points per axis of the figure sweeps
    int planarFigureGrid =
        21; // at most this with the planar model (2-5 ms of CPU a point, ~100x the 1-DOF slab)
    double sliceStep = 0.005; // g, spacing of the slice γc(A)
    bool crossCheck = true;   // run the paper solver for the error estimate
    double crossCheckSteps = 1024;
};

// Throws kinstab::InputError / ProjectError on a bad project (nothing is computed then).
// The sweep, the check, A_crit(f) and the record go through core's analysis entry point
// (core/analysis/RunAnalysis.h); control cancels all of it.
ReportAnalysis computeReportAnalysis(const Project& project, const AnalysisOptions& options = {},
                                     AnalysisControl* control = nullptr);

// The floor-motion analysis of a project with "floors" and a record (FloorsSection.cpp);
// none otherwise or after a cancel. Throws ProjectError on an unreadable record.
std::optional<FloorAnalysis> computeReportFloors(const Project& p, SweepControl* control);

// The one-sine overturning map of each of the project's blocks (BlocksSection.cpp); fewer after
// a cancel.
std::vector<OverturningMap> computeReportBlockMaps(const Project& p, SweepControl* control);

// The project's assessment from what the report ran: the sine's (or planar) check, the record's
// verdicts, the floor analysis at the slab's level (core/assessment/Assessment.h).
Assessment assessReport(const Project& project, const ReportAnalysis& a);

// The building frequency 1/T the check used (first code's period; the entered period if any).
std::optional<double> designFrequency(const Project& project, const DesignCheckResult& check);

} // namespace kinstab::report
