// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/AnalysisRuns.h"

namespace kinstab::cli {

SweepResult surfaceOf(AnalysisRequest request, const SweepGrid& grid, int threads) {
    request.grid = grid;
    request.threads = threads;
    request.parts = AnalysisParts{};
    request.parts.surface = true;
    AnalysisControl control;
    return *runAnalysis(request, control).surface;
}

nlohmann::json criticalCurveJson(AnalysisRequest request) {
    request.parts = AnalysisParts{};
    request.parts.criticalCurve = true;
    AnalysisControl control;
    const CriticalCurve c = *runAnalysis(request, control).critical;
    nlohmann::json a = nlohmann::json::array();
    for (const std::optional<double>& amplitude : c.amplitude)
        a.push_back(amplitude ? nlohmann::json(*amplitude) : nlohmann::json());
    return a;
}

} // namespace kinstab::cli
