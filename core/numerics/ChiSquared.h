// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Chi-squared distribution with k degrees of freedom: CDF and quantile (percentage point).
// Used for the confidence interval of a variance (Furgerson 1980 Table 3c).

namespace kinstab {

double chiSquaredPdf(double x, double k);
// P(X <= x) = P(k/2, x/2), the regularized lower incomplete gamma function (A&S 26.4.19).
double chiSquaredCdf(double x, double k);
// x with P(X <= x) = p, for 0 < p < 1 and k > 0 (NaN otherwise); safeguarded Newton on a bracket.
double chiSquaredQuantile(double p, double k);

} // namespace kinstab
