// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The critical peak of what drives a study case's slab (docs/studies.md, "What one case
// computes"): the driving motion itself (core/sweep/CriticalRecordScale.h), or its enveloped-sine
// surrogate - the enveloped sine of docs/theory.md §3 with the envelope fitted to the motion
// (paper Fig. 27, core/excitation/EnvelopeFit.h) at the frequency of the largest peak of the
// motion's Fourier amplitude spectrum, as kinstab-cli record reports both.

#include "core/records/Accelerogram.h"
#include "core/slab/Slab1DCase.h"
#include "core/study/StudySpec.h"
#include "core/sweep/CriticalAmplitude.h"

#include <optional>
#include <string>

namespace kinstab {

struct CaseCritical {
    std::optional<double> peak; // g, critical peak; none: no collapse up to the search limit
    double unitPeak = 0;        // g, the peak standing for the unscaled motion: its own, or the
                                // fitted envelope's for the surrogate (both scale with it)
    long runs = 0;
    std::string noFit; // the surrogate: why the motion has none (fewer than 3 half cycles, ...)
};

CaseCritical caseCritical(const Slab1DCase& slab, const Accelerogram& motion, StudyMotion kind,
                          const CriticalSearch& search);

} // namespace kinstab
