// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Closed forms of the risk integral (core/risk/RiskIntegral.h), as cross-checks beside it:
//  - first order (Cornell et al. 2002, "Probabilistic basis for 2000 SAC FEMA steel moment frame
//    guidelines", J. Struct. Eng. 128(4)): for lambda(x) = k0 x^-k,
//      lambda_C = k0 theta^-k exp(k^2 beta^2 / 2) = lambda(theta) exp(k^2 beta^2 / 2);
//  - second order (Vamvatsikos 2013, "Derivation of new SAC/FEMA performance evaluation solutions
//    with second-order hazard approximation", Earthquake Engng Struct. Dyn. 42): for
//    lambda(x) = k0 exp(-k2 ln^2 x - k1 ln x) and q = 1 / (1 + 2 k2 beta^2),
//      lambda_C = sqrt(q) k0^(1 - q) lambda(theta)^q exp(q k1^2 beta^2 / 2)
//    (the Gaussian integral of lambda against the fragility's density, valid while q > 0).
// On a tabulated curve each needs a local fit, stated with the result:
//  - first order: k is the slope of the log-log interpolated curve between theta e^-beta and
//    theta e^beta (clipped to the curve), lambda(theta) interpolated; on a quadratic in log-log
//    this symmetric secant is the tangent at theta;
//  - second order: least squares of ln lambda on a quadratic in ln x over the curve's points
//    within 2 beta (in ln x) of where the first-order integrand peaks, ln theta - k beta^2, and
//    at least the 3 points nearest it.
// Both need theta within the curve's range: elsewhere the local fit is an extrapolation.

#include "core/risk/RiskIntegral.h"

#include <cstddef>
#include <optional>
#include <string>

namespace kinstab {

double firstOrderRiskRate(double k0, double k, const CollapseFragility& f);
// none when q = 1 / (1 + 2 k2 beta^2) is not positive (the integral diverges)
std::optional<double> secondOrderRiskRate(double k0, double k1, double k2,
                                          const CollapseFragility& f);

// A form that does not apply (or overflows) says why, and its numbers are not to be read.
struct FirstOrderForm {
    std::string why;               // empty: the form applies
    double k = 0, k0 = 0;          // lambda(x) = k0 x^-k near theta, x in g
    double lambdaAtMedian = 0;     // per year
    double fitLoG = 0, fitHiG = 0; // the secant's ends
    double lambdaC = 0;
};

struct SecondOrderForm {
    std::string why;               // empty: the form applies
    double k0 = 0, k1 = 0, k2 = 0; // lambda(x) = k0 exp(-k2 ln^2 x - k1 ln x), x in g
    double fitLoG = 0, fitHiG = 0; // the fitted points' range
    std::size_t points = 0;        // fitted
    double lambdaC = 0;
};

FirstOrderForm firstOrderForm(const HazardCurve& c, const CollapseFragility& f);
SecondOrderForm secondOrderForm(const HazardCurve& c, const CollapseFragility& f);

} // namespace kinstab
