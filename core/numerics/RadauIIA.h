// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The five-stage Radau IIA collocation method (order 9, stage order 5, stiffly accurate,
// L-stable; Hairer & Wanner, Solving Ordinary Differential Equations II, 2nd ed., Springer 1996,
// §IV.5) with the embedded error estimate built as in their RADAU5 (§IV.8) and in the
// variable-order RADAU (Hairer & Wanner, "Stiff differential equations solved by Radau
// methods", J. Comput. Appl. Math. 111, 1999): with stage increments Z_i = Y_i - y0,
//   err = (u1/h I - J)^-1 (f(t0, y0) + sum_i d_i Z_i / h),
// u1 the real eigenvalue of A^-1. The weights d come from the embedded formula
//   y^ = y0 + h (f(t0, y0) / u1 + sum_i b^_i f(Y_i))  of order s = 5,
// so the estimate is of order 5; the (u1/h I - J)^-1 filter keeps it bounded on stiff components.
//
// The constants are the roots and integrals to 21 digits, computed by scripts/radau-coefficients.py
// (mpmath, 40 digits); tests/core/tst_slip_radau.cpp checks the conditions that define them.

#include "core/numerics/PredictiveStep.h"

#include <algorithm>
#include <cmath>

namespace kinstab::radau {

inline constexpr int kStages = 5;
inline constexpr double kC[kStages] = {0.0571041961145176821931, 0.27684301363812382768,
                                       0.583590432368916820057, 0.860240135656219447848, 1.0};
inline constexpr double kA[kStages][kStages] = {
    {0.0729988643179033243056, -0.0267353311079455718777, 0.0186769297639843544122,
     -0.0128791060933064398536, 0.00504283923388201520665},
    {0.153775231479182468668, 0.14621486784749350665, -0.0364445689051280895267,
     0.0212330631193047194215, -0.00793557990272877753262},
    {0.140063045684809871514, 0.298967129491283479398, 0.167585070135248963442,
     -0.0339691016866177465719, 0.0109442887441922522745},
    {0.144894308109534757537, 0.276500068760159227556, 0.325797922910421029985,
     0.128756753254909761158, -0.0157089173788053283878},
    {0.143713560791225941323, 0.281356015149462060192, 0.311826522975741254082,
     0.223103901083570744403, 0.04}};
inline constexpr double kD[kStages] = {-27.7809339440646373048, 3.64147849804921315271,
                                       -1.25254772116911872049, 0.592003167184542872566, -0.2};
// The real eigenvalue of A^-1.
inline constexpr double kU1 = 6.28670475172927664517;

// The estimate's tolerances: RADAU5's mapping rtol' = 0.1 rtol^(2/3), atol' = rtol' atol / rtol
// (for an order-3 estimate of an order-5 method). The order-5 estimate of the order-9 method
// would allow rtol^(3/5); the tighter mapping is kept (measured: see docs/theory.md §6.5).
inline double estimateRelTol(double relTol) {
    return 0.1 * std::cbrt(relTol * relTol); // cbrt: pow took 5% of the planar solver's time
}
// The scale a component of size y is measured against: atol' + rtol' y (the mapping taken once:
// a cube root per component and step was a fortieth of the planar solver's time).
struct EstimateTolerance {
    explicit EstimateTolerance(double relTol)
        : rtol(estimateRelTol(relTol)), perAbsTol(rtol / relTol) {}
    double scale(double absTol, double y) const { return perAbsTol * absTol + rtol * y; }
    double rtol, perAbsTol;
};

// The most a step may grow, and shrink, from one step to the next.
inline constexpr double kMaxGrowth = 8.0, kMaxShrink = 0.2;

// The factor by which to scale h after a step with error norm err and `newton` Newton
// iterations out of at most `maxNewton` (RADAU5's rule with the exponent 1/6 of an order-5
// estimate: a safety factor that shrinks with the iterations).
inline double stepFactor(double err, int newton, int maxNewton) {
    const double safety = 0.9 * (1.0 + 2.0 * maxNewton) / (newton + 2.0 * maxNewton);
    if (!(err > 0.0)) return kMaxGrowth;
    return std::clamp(safety / std::cbrt(std::sqrt(err)), kMaxShrink, kMaxGrowth);
}

// Gustafsson's predictive control (core/numerics/PredictiveStep.h), as in RADAU5, with the
// exponent 1/6.
inline double predictiveFactor(double h, double err, double hPrev, double errPrev) {
    const double trend = std::cbrt(std::sqrt(err * err / errPrev));
    return std::clamp(predictiveStepFactor(h, hPrev, trend), kMaxShrink, kMaxGrowth);
}

} // namespace kinstab::radau
