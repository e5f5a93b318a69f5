// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The asymptotic Coulomb law tau_inf = mu_inf * CP (Furgerson 1980, ch. III and Fig. 21):
// tau_inf = V_inf / A_b, and mu_inf is the least-squares slope of tau_inf against the
// confining pressure CP. The paper fits CP <= 400 psi only (the 500 psi tests spalled).

#include <optional>
#include <vector>

namespace kinstab {

struct CoulombPoint {
    double cpPsi = 0.0;
    double vInfKips = 0.0;
};

struct CoulombFit {
    int points = 0;
    // Slopes of V_inf (kips) against CP (psi), in kips/psi = 1000 in^2 * (psi/psi):
    // mu_inf = 1000 * slope / A_b with A_b in in^2.
    double slopeThroughOrigin = 0.0; // tau = mu CP:        sum(CP V) / sum(CP^2)
    double slopeWithIntercept = 0.0; // tau = mu CP + tau0: ordinary least squares
    double interceptKips = 0.0;      // V at CP = 0 of the second line
    std::optional<double> bearingAreaIn2;
    std::optional<double> muThroughOrigin;
    std::optional<double> muWithIntercept;
};

// Uses the points with CP <= maxCpPsi; throws std::invalid_argument when fewer than 2 distinct
// CP values remain or the bearing area is not positive.
CoulombFit fitCoulombSlope(const std::vector<CoulombPoint>& points, double maxCpPsi = 400.0,
                           std::optional<double> bearingAreaIn2 = std::nullopt);

} // namespace kinstab
