// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The abscissa of the friction-law regression (Furgerson 1980, Eq. 2):
//   xi(delta) = integral from 0 to delta of W(delta')^beta d delta',
//   W(delta)  = integral from delta_1 to delta of V(delta') d delta'   (work of the shear force).
//
// Quadrature: the samples are joined by straight lines (V piecewise linear), so W is piecewise
// quadratic and known exactly. On each interval, xi's increment is integrated by 8-point
// Gauss-Legendre after the substitution s = h t^3: W ~ V_1 s near delta_1, so W^(1/3) has an
// infinite slope there, and the substitution turns the integrand into a smooth polynomial-like
// function (the plain trapezoid rule errs by several per cent on the first interval).
// For beta = 0, xi = delta - delta_1 exactly.

#include <Eigen/Core>

namespace kinstab {

// Cumulative work W at each sample (trapezoid = exact for the polyline), W(0) = 0.
Eigen::VectorXd cumulativeWork(const Eigen::VectorXd& delta, const Eigen::VectorXd& shear);

// xi at each sample; beta >= 0. Shear must be positive (W increasing).
Eigen::VectorXd workAbscissa(const Eigen::VectorXd& delta, const Eigen::VectorXd& shear,
                             double beta);

} // namespace kinstab
