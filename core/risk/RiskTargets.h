// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The code's risk targets (ASCE 7-22 ch. 21 and the USGS risk-targeted ground motion behind it):
// a 1 % probability of collapse in 50 years, lambda = -ln(0.99) / 50 = 2.0101e-4 per year, and a
// 10 % probability of collapse given the risk-targeted motion, so that the fragility's median is
// theta = x10 exp(1.2816 beta), x10 the intensity at which P(C) = 10 %.

#include "core/risk/RiskIntegral.h"

#include <optional>
#include <string>

namespace kinstab {

// -ln(0.99) / 50 per year: 1 % in 50 years (Poisson).
double codeTargetRate();
inline constexpr double kTargetConditionalProbability = 0.10;
// Phi^-1(0.1): Phi of it is 0.1 to 1e-16 (tests/core/tst_risk_integral.cpp).
inline constexpr double kNormalQuantile10 = -1.2815515655446004;

// The intensity at which P(C) = 10 %: theta exp(beta Phi^-1(0.1)).
double imAtTenPercent(const CollapseFragility& f);

struct RiskTargetedMedian {
    std::optional<double> medianG; // none: see why
    std::string why;
    int iterations = 0; // bisection steps on ln theta
};

// The median theta at which lambda_C(theta, beta) (the rule of riskIntegral) equals the target
// rate. lambda_C falls from lambda(x_min) (theta -> 0) to 0 (theta -> infinity), so there is one
// root when the target lies below lambda(x_min); it is bracketed and bisected on ln theta to
// 1e-12 (at most 200 steps).
RiskTargetedMedian riskTargetedMedian(const HazardCurve& c, double beta, double targetRate);

} // namespace kinstab
