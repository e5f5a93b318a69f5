// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/risk/RiskAnalysis.h"

#include "core/numerics/Quantile.h"

#include <algorithm>

namespace kinstab {

RiskResult analyzeRisk(const HazardCurve& c, const CollapseFragility& f, const RiskSettings& s) {
    RiskResult r;
    r.fragility = f;
    r.integral = riskIntegral(c, f);
    r.pInYears = probabilityInYears(r.integral.lambdaC, s.years);
    r.firstOrder = firstOrderForm(c, f);
    r.secondOrder = secondOrderForm(c, f);
    r.targeted = riskTargetedMedian(c, f.beta, s.targetRate);
    r.imAtTenPercent = imAtTenPercent(f);
    if (s.imG) r.pAtIm = collapseProbability(f, *s.imG);
    return r;
}

namespace {

RiskPercentiles percentiles(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return {quantile(v, 0.05), quantile(v, 0.50), quantile(v, 0.95)};
}

} // namespace

RiskBootstrap riskBootstrap(const HazardCurve& c,
                            const std::vector<std::optional<LognormalFit>>& resamples,
                            double years) {
    RiskBootstrap b;
    b.resamples = resamples.size();
    std::vector<double> rates, probabilities;
    for (const std::optional<LognormalFit>& fit : resamples) {
        const double rate = fit ? riskIntegral(c, {fit->median, fit->beta}).lambdaC : 0.0;
        b.fitted += fit ? 1 : 0;
        rates.push_back(rate);
        probabilities.push_back(probabilityInYears(rate, years));
    }
    b.lambdaC = percentiles(rates);
    b.pInYears = percentiles(probabilities);
    return b;
}

} // namespace kinstab
