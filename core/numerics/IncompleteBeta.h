// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Regularized incomplete beta function I_x(a, b). Basis of the Student t distribution.

namespace kinstab {

// I_x(a, b) for a, b > 0 and 0 <= x <= 1 (NaN otherwise). Continued fraction of
// Abramowitz & Stegun 26.5.8, evaluated by the modified Lentz method, on the side of
// x = (a+1)/(a+b+2) where it converges fast (symmetry I_x(a,b) = 1 - I_{1-x}(b,a)).
double regularizedIncompleteBeta(double a, double b, double x);

} // namespace kinstab
