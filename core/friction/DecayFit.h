// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Fitting the decay law to one curve: V_inf by a bracketed 1-D minimization of f_m
// (Furgerson 1980, Eq. 5 and Fig. 17), c and b in closed form at each trial V_inf
// (core/friction/DecayRegression.h), and the better of beta = 0 and beta = 1/3.

#include "core/friction/TripletCurve.h"

#include <Eigen/Core>

#include <vector>

namespace kinstab {

struct DecayFitOptions {
    double alpha = 2.0; // weight exponent; the paper uses 2 throughout (Table 3a)
    // V_inf is searched on [lowerBound, min V_i - boundGap]: V_inf must stay below every sample
    // (eta_i = log of a ratio) and a friction force is not negative. The gap matches the
    // "+10^-6" the paper prints on V_inf (Table 3a).
    double lowerBound = 0.0;
    double boundGap = 1e-6;
    int scanPoints = 400; // coarse scan that brackets the global minimum before Brent
};

struct DecayFit {
    double alpha = 2.0;
    double beta = 0.0;
    double v1 = 0.0;   // shear at delta_1 (peak)
    double vInf = 0.0; // asymptotic shear
    double c = 0.0;
    double b = 0.0;
    double fm = 0.0;           // mean squared residual (kips^2)
    double vInfUpper = 0.0;    // the bound min V_i - gap
    bool atUpperBound = false; // minimum on the bound (within 1e-6 kips)
    Eigen::VectorXd xi;        // regression abscissae
    Eigen::VectorXd fitted;    // V(delta_i) of the fitted law
};

// The fit for one beta. The curve must pass validateCurve(); throws std::invalid_argument
// otherwise.
DecayFit fitDecay(const TripletCurve& curve, double beta, const DecayFitOptions& options = {});

// The fit with the smallest f_m over the given betas (the paper: "beta is chosen equal to 0 or
// 1/3 whichever gives the best result").
DecayFit fitDecayBestBeta(const TripletCurve& curve,
                          const std::vector<double>& betas = {0.0, 1.0 / 3.0},
                          const DecayFitOptions& options = {});

// The fitted law at arbitrary displacements (for plotting), with xi from the same polyline
// quadrature: V at the curve's samples is interpolated linearly.
Eigen::VectorXd evaluateDecay(const DecayFit& fit, const TripletCurve& curve,
                              const Eigen::VectorXd& delta);

} // namespace kinstab
