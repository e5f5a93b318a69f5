// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The three-stage Radau IIA collocation method (order 5, stiffly accurate, L-stable) and the
// embedded error estimate of Hairer & Wanner's RADAU5 (Solving Ordinary Differential Equations
// II, 2nd ed., Springer 1996, §IV.8): with stage increments Z_i = Y_i - y0,
//   err = (u1/h I - J)^-1 (f(t0, y0) + (d1 Z1 + d2 Z2 + d3 Z3) / h),
// an estimate of order 3 whose (u1/h I - J)^-1 filter keeps it bounded on stiff components.

#include <algorithm>
#include <cmath>

namespace kinstab::radau {

inline const double kSqrt6 = std::sqrt(6.0);
inline const double kC[3] = {(4.0 - kSqrt6) / 10.0, (4.0 + kSqrt6) / 10.0, 1.0};
inline const double kA[3][3] = {{(88.0 - 7.0 * kSqrt6) / 360.0, (296.0 - 169.0 * kSqrt6) / 1800.0,
                                 (-2.0 + 3.0 * kSqrt6) / 225.0},
                                {(296.0 + 169.0 * kSqrt6) / 1800.0, (88.0 + 7.0 * kSqrt6) / 360.0,
                                 (-2.0 - 3.0 * kSqrt6) / 225.0},
                                {(16.0 - kSqrt6) / 36.0, (16.0 + kSqrt6) / 36.0, 1.0 / 9.0}};
inline const double kD[3] = {-(13.0 + 7.0 * kSqrt6) / 3.0, (-13.0 + 7.0 * kSqrt6) / 3.0,
                             -1.0 / 3.0};
// The real eigenvalue of A^-1.
inline const double kU1 = 30.0 / (6.0 + std::cbrt(81.0) - std::cbrt(9.0));

// RADAU5's tolerances for its order-3 estimate: rtol' = 0.1 rtol^(2/3), atol' = rtol' atol / rtol.
inline double estimateRelTol(double relTol) {
    return 0.1 * std::cbrt(relTol * relTol); // cbrt: pow took 5% of the planar solver's time
}
// The scale a component of size y is measured against: atol' + rtol' y.
inline double estimateScale(double absTol, double relTol, double y) {
    const double rtol = estimateRelTol(relTol);
    return rtol * absTol / relTol + rtol * y;
}

// The factor by which to scale h after a step with error norm err and `newton` Newton
// iterations out of at most `maxNewton` (RADAU5's rule: exponent 1/4, a safety factor that
// shrinks with the iterations, limited to [0.2, 8]).
inline double stepFactor(double err, int newton, int maxNewton) {
    const double safety = 0.9 * (1.0 + 2.0 * maxNewton) / (newton + 2.0 * maxNewton);
    if (!(err > 0.0)) return 8.0;
    return std::clamp(safety / std::sqrt(std::sqrt(err)), 0.2, 8.0);
}

} // namespace kinstab::radau
