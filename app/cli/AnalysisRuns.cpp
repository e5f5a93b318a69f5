// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/AnalysisRuns.h"

#include "app/cli/ModelFlags.h"
#include "app/cli/PlanarFlags.h"
#include "app/cli/ProgressLine.h"
#include "core/io/CaseJson.h"

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

nlohmann::json modelKeysJson(const AnalysisRequest& q) {
    if (const std::optional<PlanarCase> c = q.planarCase()) return planarCaseJson(*c);
    return {{"model", modelKindName(ModelKind::Slab1D)},
            {"solver", solverName(q.slab.solver)},
            {"envelope", envelopeJson(q.slab)},
            {"mu", q.slab.slab.mu},
            {"tstar", q.slab.tstar}};
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

nlohmann::json criticalCurveJson(AnalysisRequest request) {
    request.parts = AnalysisParts{};
    request.parts.criticalCurve = true;
    AnalysisControl control;
    std::optional<CriticalCurve> curve;
    {
        const ProgressLine progress("critical", "frequencies", [&control] {
            return std::pair(control.done(), control.total());
        });
        curve = runAnalysis(request, control).critical;
    }
    const CriticalCurve c = *curve;
    nlohmann::json a = nlohmann::json::array();
    for (const std::optional<double>& amplitude : c.amplitude)
        a.push_back(amplitude ? nlohmann::json(*amplitude) : nlohmann::json());
    return a;
}

} // namespace kinstab::cli
