// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/building/ModalModel.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <numbers>
#include <numeric>

namespace kinstab {

ModalModel modalModel(const ShearBuilding& s) {
    const Eigen::MatrixXd M = massMatrix(s);
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(stiffnessMatrix(s), M);
    const Eigen::VectorXd ones = Eigen::VectorXd::Ones(M.rows());
    const double totalMass = std::accumulate(s.masses.begin(), s.masses.end(), 0.0);
    ModalModel model;
    model.heights = s.heights;
    for (Eigen::Index r = 0; r < M.rows(); ++r) {
        Eigen::VectorXd phi = solver.eigenvectors().col(r);
        // The roof is never a node of a shear building's mode (the top spring is free), so
        // scaling it to +1 is always possible and fixes the sign.
        phi /= phi(phi.size() - 1);
        const double modalMass = phi.dot(M * phi);
        Mode m;
        m.omega = std::sqrt(solver.eigenvalues()(r));
        m.period = 2.0 * std::numbers::pi / m.omega;
        m.participation = phi.dot(M * ones) / modalMass;
        m.effectiveMass = m.participation * m.participation * modalMass / totalMass;
        m.shape.assign(phi.data(), phi.data() + phi.size());
        model.modes.push_back(m);
    }
    return model;
}

} // namespace kinstab
