// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The post-fracture decay law and its linear regression for a given V_inf
// (Furgerson 1980, ch. III, Eqs. 2-5):
//   (V(delta) - V_inf) / (V_1 - V_inf) = exp(-(c xi(delta) + b))
//   eta_i = log((V_1 - V_inf) / (V_i - V_inf)),  eta_i ~ c xi_i + b,
//   M(c, b) = sum (V_i - V_inf)^alpha (eta_i - c xi_i - b)^2.

#include <Eigen/Core>

namespace kinstab {

struct DecayLine {
    double c = 0.0;     // decay rate (1/in for beta = 0)
    double b = 0.0;     // offset at delta_1 (no unit)
    bool valid = false; // false when the normal equations are singular
};

// c and b from dM/dc = dM/db = 0 (Eqs. 3, 4) in closed form, with weights w_i = (V_i -
// V_inf)^alpha:
//   c = (S_w S_wxe - S_wx S_we) / (S_w S_wxx - S_wx^2),  b = (S_we - c S_wx) / S_w.
// Requires V_inf < min V_i.
DecayLine fitDecayLine(const Eigen::VectorXd& xi, const Eigen::VectorXd& shear, double vInf,
                       double alpha);

// V(delta_i) of Eq. 2 at the given abscissae; v1 is the shear at delta_1.
Eigen::VectorXd decayModel(const Eigen::VectorXd& xi, double v1, double vInf,
                           const DecayLine& line);

// f_m = (1/n) sum (V_i - V(delta_i))^2 (Eq. 5) for the line fitted at this V_inf;
// +infinity when the fit is singular or V_inf is not below every sample.
double decayMeanSquare(const Eigen::VectorXd& xi, const Eigen::VectorXd& shear, double vInf,
                       double alpha);

} // namespace kinstab
