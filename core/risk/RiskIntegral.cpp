// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/risk/RiskIntegral.h"

#include "core/numerics/NormalTail.h"

#include <cmath>
#include <numbers>

namespace kinstab {

namespace {

// ln phi(0) + ... : ln sqrt(2 pi), the normal density's constant.
const double kLnSqrt2Pi = 0.5 * std::log(2.0 * std::numbers::pi);

// G = integral over [sa, sb] of lambda(s) N(s; mu, beta^2) ds, s = ln x, where on the segment
// lambda(s) = la exp(-k (s - sa)). Completing the square,
//   G = la exp(k (sa - mu) + k^2 beta^2 / 2) [Phi(zb) - Phi(za)],  z = (s - mu + k beta^2) / beta.
// The exponential overflows where the Phi difference underflows (a steep segment far above the
// median, or a wide beta), so in either tail the two are combined in logarithms through the
// Mills ratio, where the large terms cancel exactly:
//   za >= 0: k (sa - mu) + k^2 beta^2 / 2 - za^2 / 2 = -(sa - mu)^2 / (2 beta^2)
//   zb <= 0: k (sa - mu) + k^2 beta^2 / 2 - zb^2 / 2 = ln(lb / la) - (sb - mu)^2 / (2 beta^2).
double segmentIntegral(double sa, double sb, double la, double lb, double mu, double beta) {
    const double k = std::log(la / lb) / (sb - sa); // >= 0: rates do not increase
    const double shift = k * beta * beta;
    const double za = (sa - mu + shift) / beta, zb = (sb - mu + shift) / beta;
    if (za >= 0.0) { // both in the upper tail: Phi(zb) - Phi(za) = Q(za) - Q(zb)
        const double ratio = std::exp(logNormalTail(zb) - logNormalTail(za));
        const double d = (sa - mu) / beta;
        return la *
               std::exp(-0.5 * d * d - kLnSqrt2Pi + std::log(millsRatio(za)) + std::log1p(-ratio));
    }
    if (zb <= 0.0) { // both in the lower tail: Phi(z) = Q(-z)
        const double ratio = std::exp(logNormalTail(-za) - logNormalTail(-zb));
        const double d = (sb - mu) / beta;
        return lb *
               std::exp(-0.5 * d * d - kLnSqrt2Pi + std::log(millsRatio(-zb)) + std::log1p(-ratio));
    }
    // za < 0 < zb: the exponent is below -k^2 beta^2 / 2 <= 0, nothing overflows.
    return la * std::exp(k * (sa - mu) + 0.5 * shift * k) * (normalCdf(zb) - normalCdf(za));
}

} // namespace

double collapseProbability(const CollapseFragility& f, double imG) {
    return normalCdf(std::log(imG / f.medianG) / f.beta);
}

double probabilityInYears(double annualRate, double years) {
    return -std::expm1(-years * annualRate);
}

// Integrating P |d lambda| by parts on each segment gives la Pa - lb Pb + G; the first two terms
// telescope over the segments, so lambda_C = lambda(x_min) P(x_min) + sum of G (the rate beyond
// the last point, lambda(x_max) P(x_max), cancels the last -lb Pb): a sum of positive terms,
// with no cancellation.
RiskIntegral riskIntegral(const HazardCurve& curve, const CollapseFragility& f) {
    const auto& p = curve.points;
    const double mu = std::log(f.medianG);
    RiskIntegral r;
    r.pAtFirstPoint = collapseProbability(f, p.front().imG);
    r.pAtLastPoint = collapseProbability(f, p.back().imG);
    double sum = p.front().annualRate * r.pAtFirstPoint;
    for (std::size_t i = 0; i + 1 < p.size(); ++i)
        sum += segmentIntegral(std::log(p[i].imG), std::log(p[i + 1].imG), p[i].annualRate,
                               p[i + 1].annualRate, mu, f.beta);
    r.lambdaC = sum;
    r.beyondLastPoint = p.back().annualRate * r.pAtLastPoint;
    r.withinCurve = r.lambdaC - r.beyondLastPoint;
    return r;
}

} // namespace kinstab
