// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Gustafsson's predictive step-size control (K. Gustafsson, ACM TOMS 20, 1994; as in Hairer &
// Wanner's RADAU5, Solving ODEs II, §IV.8): after two accepted steps in a row the next step is
// also at most the one that the trend of the error from the previous step to this one predicts,
//   h_new / h = 0.9 (h / hPrev) / (err^2 / errPrev)^(1/q),
// errPrev floored at 1e-2, q the estimate's order + 1. It anticipates an error that grows step
// after step, as it does while a slip slows down, where the plain factor 0.9 err^(-1/q) would be
// rejected in turn. `trend` is (err^2 / errPrev)^(1/q), taken by the caller without pow; the
// caller limits the factor as its plain one.

namespace kinstab {

inline double predictiveStepFactor(double h, double hPrev, double trend) {
    return 1.0 / ((hPrev / h) * trend / 0.9);
}

} // namespace kinstab
