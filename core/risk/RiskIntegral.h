// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The annual rate of collapse lambda_C = integral of P(C | x) |d lambda(x)| (Cornell & Krawinkler
// 2000; docs/studies.md, "Risk"), with a lognormal fragility P(C | x) = Phi(ln(x / theta) / beta)
// and a tabulated hazard curve. The rule, stated in every output because it alone moves results
// by percent to tens of percent between tools:
//  - lambda(x) is linear in log-log between the curve's points (a power law on each segment);
//  - each segment's integral is taken in closed form (a Gaussian integral of a power law), so
//    there is no quadrature error: the rule, not the arithmetic, sets the result;
//  - the rate beyond the last point, lambda(x_max), is counted with P(C | x_max) (a lower bound
//    of what larger intensities add);
//  - intensities below the first point add no rate: lambda(x) is taken as lambda(x_min) there,
//    so P(C | x_min) is what the curve's start leaves out per unit of rate below it.

#include "core/risk/HazardCurve.h"

namespace kinstab {

struct CollapseFragility {
    double medianG = 0; // theta, g
    double beta = 0;    // dispersion of ln IM
};

// Phi(ln(x / theta) / beta).
double collapseProbability(const CollapseFragility& f, double imG);
// 1 - exp(-years lambda), the probability of at least one collapse in the years (Poisson).
double probabilityInYears(double annualRate, double years);

struct RiskIntegral {
    double lambdaC = 0;         // per year, the whole rule
    double withinCurve = 0;     // per year, the part between the first and the last point
    double beyondLastPoint = 0; // per year, lambda(x_max) P(C | x_max)
    double pAtFirstPoint = 0, pAtLastPoint = 0;
};

RiskIntegral riskIntegral(const HazardCurve& curve, const CollapseFragility& f);

} // namespace kinstab
