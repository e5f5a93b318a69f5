// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/building/ShearBuilding.h"

#include "core/codes/Asce7_22.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <numbers>
#include <numeric>

namespace kinstab {

namespace {

// Storey stiffness ratios of the profile: uniform, or the weight each storey carries.
std::vector<double> profileStiffness(const std::vector<double>& masses, StiffnessProfile p) {
    std::vector<double> k(masses.size(), 1.0);
    if (p == StiffnessProfile::Weight) {
        double carried = 0;
        for (std::size_t i = masses.size(); i-- > 0;)
            k[i] = (carried += masses[i]);
    }
    return k;
}

double firstCircularFrequency(const ShearBuilding& s) {
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(
        stiffnessMatrix(s), massMatrix(s), Eigen::EigenvaluesOnly);
    return std::sqrt(solver.eigenvalues()(0));
}

} // namespace

ShearBuilding shearBuilding(const Building& b, StiffnessProfile profile) {
    requireValidBuilding(b);
    ShearBuilding s;
    const std::vector<double> w = levelWeights(b);
    const double mean = std::accumulate(w.begin(), w.end(), 0.0) / static_cast<double>(w.size());
    for (double x : w)
        s.masses.push_back(x / mean);
    s.heights = levelHeights(b);
    s.period = b.period.value_or(asce7ApproximatePeriod(b));
    s.periodSource = b.period ? "entered" : "ASCE 7-22 T_a (no period entered)";
    s.stiffness = profileStiffness(s.masses, profile);
    // Every omega scales with sqrt(k): one factor puts the first period at T.
    const double target = 2.0 * std::numbers::pi / s.period;
    const double w1 = firstCircularFrequency(s);
    for (double& k : s.stiffness)
        k *= (target / w1) * (target / w1);
    return s;
}

Eigen::MatrixXd massMatrix(const ShearBuilding& s) {
    const auto n = static_cast<Eigen::Index>(s.masses.size());
    Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n, n);
    for (Eigen::Index i = 0; i < n; ++i)
        m(i, i) = s.masses[static_cast<std::size_t>(i)];
    return m;
}

Eigen::MatrixXd stiffnessMatrix(const ShearBuilding& s) {
    const auto n = static_cast<Eigen::Index>(s.stiffness.size());
    const auto k = [&](Eigen::Index i) {
        return i < n ? s.stiffness[static_cast<std::size_t>(i)] : 0.0;
    };
    Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n);
    for (Eigen::Index i = 0; i < n; ++i) {
        K(i, i) = k(i) + k(i + 1);
        if (i + 1 < n) K(i, i + 1) = K(i + 1, i) = -k(i + 1);
    }
    return K;
}

} // namespace kinstab
