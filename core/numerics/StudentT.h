// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Student's t distribution with nu degrees of freedom: CDF and quantile (percentage point).
// Used for the confidence interval of a mean (Furgerson 1980 Table 3c) and Grubbs' test.

namespace kinstab {

double studentTPdf(double t, double nu);
// P(T <= t) = 1 - I_{nu/(nu+t^2)}(nu/2, 1/2) / 2 for t >= 0 (A&S 26.7.1 with 26.5.27).
double studentTCdf(double t, double nu);
// t with P(T <= t) = p, for 0 < p < 1 and nu > 0 (NaN otherwise); the root of CDF - p on a
// bracket, by safeguarded Newton (core/numerics/RootFinding.h).
double studentTQuantile(double p, double nu);

} // namespace kinstab
