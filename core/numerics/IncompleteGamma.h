// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Regularized lower incomplete gamma function P(a, x). Basis of the chi-squared distribution.

namespace kinstab {

// P(a, x) for a > 0, x >= 0 (NaN otherwise): the power series (A&S 6.5.29) below x = a + 1,
// the continued fraction for Q = 1 - P (A&S 6.5.31, modified Lentz) above, where each converges
// fast.
double regularizedLowerGamma(double a, double x);

} // namespace kinstab
