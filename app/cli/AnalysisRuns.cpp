// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/AnalysisRuns.h"

#include "app/cli/ProgressLine.h"

#include <optional>
#include <utility>

namespace kinstab::cli {

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
