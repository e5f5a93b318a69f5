// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/risk/RiskTargets.h"

#include "core/base/TextInput.h"

#include <cmath>

namespace kinstab {

double codeTargetRate() {
    return -std::log(0.99) / 50.0;
}

double imAtTenPercent(const CollapseFragility& f) {
    return f.medianG * std::exp(f.beta * kNormalQuantile10);
}

namespace {

constexpr int kMaxBracketSteps = 100; // of beta each: far beyond any curve's range
constexpr int kMaxBisections = 200;

// ln lambda_C - ln target at ln theta = u: decreasing in u.
double excess(const HazardCurve& c, double beta, double target, double u) {
    return std::log(riskIntegral(c, {std::exp(u), beta}).lambdaC) - std::log(target);
}

} // namespace

RiskTargetedMedian riskTargetedMedian(const HazardCurve& c, double beta, double targetRate) {
    RiskTargetedMedian r;
    const double top = c.points.front().annualRate;
    if (!(targetRate < top)) {
        r.why = "every median meets the target: the curve's largest rate " + formatDouble(top) +
                " per year (at " + formatDouble(c.points.front().imG) + " g) is not above " +
                formatDouble(targetRate);
        return r;
    }
    // Bracket: from beyond each end of the curve, stepping out by beta until the sign holds.
    double lo = std::log(c.points.front().imG) - 8.0 * beta;
    double hi = std::log(c.points.back().imG) + 8.0 * beta;
    for (int k = 0; k < kMaxBracketSteps && excess(c, beta, targetRate, lo) <= 0.0; ++k)
        lo -= beta;
    for (int k = 0; k < kMaxBracketSteps && excess(c, beta, targetRate, hi) >= 0.0; ++k)
        hi += beta;
    if (!(excess(c, beta, targetRate, lo) > 0.0 && excess(c, beta, targetRate, hi) < 0.0)) {
        r.why = "the target rate " + formatDouble(targetRate) +
                " is not bracketed within 100 beta of the curve's ends";
        return r;
    }
    for (r.iterations = 1; r.iterations <= kMaxBisections && hi - lo > 1e-12; ++r.iterations) {
        const double mid = 0.5 * (lo + hi);
        (excess(c, beta, targetRate, mid) > 0.0 ? lo : hi) = mid;
    }
    r.medianG = std::exp(0.5 * (lo + hi));
    return r;
}

} // namespace kinstab
