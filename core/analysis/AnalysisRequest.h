// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a project asks of one analysis run: the model (the 1-DOF slab, or the planar slab of
// Furgerson 1980 ch. VI), the excitation (the enveloped sine of the slab case, or a record), and
// which parts to compute. Parts not asked for are not computed.

#include "core/codes/CodeResult.h"
#include "core/excitation/RecordExcitation.h"
#include "core/slab/PlanarCase.h"
#include "core/slab/Slab1DCase.h"
#include "core/sweep/CriticalAmplitude.h"
#include "core/sweep/Grid.h"

#include <optional>
#include <vector>

namespace kinstab {

struct AnalysisParts {
    bool surface = false;       // γc over `grid` (enveloped sine)
    bool criticalCurve = false; // A_crit at `criticalFrequencies` (enveloped sine)
    bool designCheck = false;   // each code against A_crit(1/T) of the sine (ch. V)
    bool recordCheck = false;   // the record's run, critical peak and each code's verdict
};

struct AnalysisRequest {
    // The model: the 1-DOF case, and with `planar` set the planar model of that case (its μ,
    // envelope, t*, scale, limit and duration are `slab`'s: they live here once).
    Slab1DCase slab;
    std::optional<PlanarInputs> planar;     // set: the planar model runs the sine parts
    std::optional<RecordExcitation> record; // the record of recordCheck (1-DOF slab)
    SweepGrid grid;                         // of the surface
    std::vector<double> criticalFrequencies;
    CriticalSearch criticalSearch; // of the A_crit(f) curve
    std::vector<CodeResult> codes; // of the checks
    CriticalSearch checkSearch;    // of the checks' A_crit searches
    AnalysisParts parts;
    // 1-DOF: each run is checked (core/slab/FiniteResult.h) and an unsound one throws
    // InternalError instead of counting as an outcome (kinstab-cli's exit 3).
    bool requireSoundRuns = false;
    int threads = 0; // 0: all hardware threads

    // The planar case the sine parts run when `planar` is set.
    std::optional<PlanarCase> planarCase() const {
        if (!planar) return std::nullopt;
        return PlanarCase(slab, *planar);
    }
};

} // namespace kinstab
