// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/AnalysisRuns.h"

#include "app/cli/ModelFlags.h"
#include "app/cli/PlanarFlags.h"
#include "app/cli/ProgressLine.h"

#include <optional>
#include <utility>

namespace kinstab::cli {

AnalysisRequest modelRequestFromFlags(const Args& args) {
    AnalysisRequest q;
    if (!isPlanar(args)) {
        q.slab = slab1DCaseFromFlags(args);
        return q;
    }
    const PlanarCase c = planarCaseFromFlags(args);
    q.slab = c.common;
    q.planar = c.own();
    return q;
}

SweepResult surfaceOf(AnalysisRequest request, const SweepGrid& grid, int threads) {
    request.grid = grid;
    request.threads = threads;
    request.parts = AnalysisParts{};
    request.parts.surface = true;
    AnalysisControl control;
    const ProgressLine progress("surface", "points",
                                [&control] { return std::pair(control.done(), control.total()); });
    return *runAnalysis(request, control).surface;
}

CriticalCurve criticalCurveOf(AnalysisRequest request) {
    request.parts = AnalysisParts{};
    request.parts.criticalCurve = true;
    AnalysisControl control;
    const ProgressLine progress("critical", "frequencies",
                                [&control] { return std::pair(control.done(), control.total()); });
    return *runAnalysis(request, control).critical;
}

} // namespace kinstab::cli
