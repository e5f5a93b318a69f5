// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Where the risk comes from (docs/studies.md, "Risk"): the integrand of lambda_C per unit of
// ln x, d lambda_C / d ln x = P(C | x) |d lambda / d ln x|, under the rule of
// core/risk/RiskIntegral.h. On a segment of the curve lambda(x) = la (x / xa)^-k, so
// |d lambda / d ln x| = k lambda(x): the integrand jumps where the slope changes, at the curve's
// points. Its area over ln x from x_min to x_max is RiskIntegral::withinCurve; the rest of
// lambda_C, the rate beyond the last point, is a mass at x_max (RiskIntegral::beyondLastPoint).
// Plotted against log x, the area under it shows which intensities drive the risk.

#include "core/risk/RiskIntegral.h"

#include <cstddef>
#include <vector>

namespace kinstab {

struct RiskIntegrandPoint {
    double imG = 0;        // g
    double annualRate = 0; // lambda(x), per year
    double pCollapse = 0;  // P(C | x)
    double density = 0;    // d lambda_C / d ln x, per year
};

// A sampling fine enough for a chart: segments of a tabulated curve are a few tenths of a
// decade wide, and 24 points per segment follow the fragility's bend on each.
inline constexpr std::size_t kIntegrandPointsPerSegment = 24;

// perSegment + 1 points on each segment (the first and last at the curve's points, so each
// segment's ends appear once per segment, with that segment's slope). perSegment >= 1.
std::vector<RiskIntegrandPoint> riskIntegrand(const HazardCurve& curve, const CollapseFragility& f,
                                              std::size_t perSegment = kIntegrandPointsPerSegment);

} // namespace kinstab
