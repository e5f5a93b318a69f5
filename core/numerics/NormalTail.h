// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The standard normal distribution far into its tails. Phi(z) = 0.5 erfc(-z / sqrt 2) underflows
// beyond |z| of about 38, and a risk integral multiplies such a tail by an exponential that
// overflows (core/risk/RiskIntegral.cpp): both are kept finite by working with the Mills ratio
// R(z) = Q(z) / phi(z), Q = 1 - Phi, which is about 1/z far out and never under- or overflows.

namespace kinstab {

double normalCdf(double z);  // Phi(z)
double normalTail(double z); // Q(z) = 1 - Phi(z), accurate where Phi(z) rounds to 1
// exp(x^2) erfc(x) for x >= 0 (the scaled complementary error function).
double erfcx(double x);
// R(z) = Q(z) / phi(z) for z >= 0: sqrt(pi/2) erfcx(z / sqrt 2).
double millsRatio(double z);
// ln Q(z) for z >= 0, finite however large z is.
double logNormalTail(double z);

} // namespace kinstab
