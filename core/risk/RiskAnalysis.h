// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Everything kinstab says about one fragility on one hazard curve (docs/studies.md, "Risk"): the
// risk integral and its rule, the probability in N years, the closed forms beside it, and the
// code's targets; and, over a study's bootstrap resamples, the percentiles of lambda_C.

#include "core/risk/RiskClosedForms.h"
#include "core/risk/RiskTargets.h"
#include "core/study/LognormalFit.h"

#include <cstddef>
#include <optional>
#include <vector>

namespace kinstab {

struct RiskSettings {
    double years = 50;                    // of the probability of collapse
    double targetRate = codeTargetRate(); // per year
    std::optional<double> imG;            // g, e.g. the site's MCE_R: P(C) there against 10 %
};

struct RiskResult {
    CollapseFragility fragility;
    RiskIntegral integral;
    double pInYears = 0;
    FirstOrderForm firstOrder;
    SecondOrderForm secondOrder;
    RiskTargetedMedian targeted; // for the fragility's beta
    double imAtTenPercent = 0;   // g
    std::optional<double> pAtIm; // at settings.imG
};

RiskResult analyzeRisk(const HazardCurve& c, const CollapseFragility& f, const RiskSettings& s);

struct RiskPercentiles {
    double p5 = 0, p50 = 0, p95 = 0;
};

struct RiskBootstrap {
    std::size_t resamples = 0, fitted = 0;
    RiskPercentiles lambdaC, pInYears;
};

// lambda_C and its probability in years over the resamples (core/study/Fragility.h,
// fragilityResamples). A resample that cannot be fitted has its median beyond the intensities it
// shows (the fragility's convention): it counts as lambda_C = 0. resamples: not empty.
RiskBootstrap riskBootstrap(const HazardCurve& c,
                            const std::vector<std::optional<LognormalFit>>& resamples,
                            double years);

} // namespace kinstab
