// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What runAnalysis (core/analysis/RunAnalysis.h) computed: each part asked for, or nothing for a
// part not asked for or not reached before a cancel.

#include "core/analysis/CriticalCurve.h"
#include "core/check/DesignCheck.h"
#include "core/check/RecordAnalysis.h"
#include "core/sweep/Sweep.h"

#include <exception>
#include <optional>
#include <string>

namespace kinstab {

struct AnalysisResult {
    double tauRef = 1;   // γc = tauRef / τc of the model
    double scanFrom = 0; // where every A_crit scan started, below which nothing slips
    std::optional<SweepResult> surface; // after a cancel: the points done so far
    std::optional<CriticalCurve> critical;
    std::optional<DesignCheckResult> check;
    // Why the design check failed (an InputError on a bad case, search or period): the surface
    // and the curve are kept. Rethrow it with std::rethrow_exception to report it.
    std::exception_ptr checkError;
    std::optional<RecordAnalysis> record;
    bool cancelled = false; // then the curve and the checks are dropped: they may be partial
    double surfaceSeconds = 0, criticalSeconds = 0, checkSeconds = 0, recordSeconds = 0;
};

// checkError's message, for a view that shows it beside the verdicts; empty when none.
inline std::string checkErrorMessage(const AnalysisResult& r) {
    if (!r.checkError) return {};
    try {
        std::rethrow_exception(r.checkError);
    } catch (const std::exception& e) {
        return e.what();
    } catch (...) {
        return "unknown error";
    }
}

} // namespace kinstab
