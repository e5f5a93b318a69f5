// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One parameter set of a study on a hazard curve (docs/studies.md, "Risk"): its fitted fragility
// (the fit alone), the risk of that fit, lambda_C over the bootstrap's resamples and the
// integrand - what `kinstab-cli risk --results R --set K` writes and the Study tab shows, from one
// computation.

#include "core/risk/RiskAnalysis.h"
#include "core/risk/RiskIntegrand.h"
#include "core/study/Fragility.h"
#include "core/sweep/SweepControl.h"

#include <optional>
#include <vector>

namespace kinstab {

struct SetRisk {
    Fragility fragility;                    // fitted without resamples (its bounds are empty)
    std::optional<RiskResult> risk;         // none: no fit (fragility.noFit says why)
    std::optional<RiskBootstrap> bootstrap; // none: no fit, or b.resamples == 0
    std::vector<RiskIntegrandPoint> integrand;
    // target rate / lambda_C, as the assessment's risk check (core/assessment/Assessment.cpp);
    // none when lambda_C is 0 to double precision.
    std::optional<double> margin;
};

// rows: one parameter set's rows. Throws StudyError when the bootstrap exceeds its bound.
SetRisk setRisk(const HazardCurve& c, const std::vector<StudyRow>& rows, const RiskSettings& s,
                const BootstrapSettings& b);

// Every parameter set of a study's rows (any order), in set order. Stops between sets once
// control is cancelled (then fewer sets come back); progress(done, total) after each set.
std::vector<SetRisk> studySetRisks(const HazardCurve& c, const std::vector<StudyRow>& rows,
                                   const RiskSettings& s, const BootstrapSettings& b,
                                   const SweepControl* control = nullptr);

} // namespace kinstab
