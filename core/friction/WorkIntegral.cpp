// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/friction/WorkIntegral.h"

#include <array>
#include <cmath>

namespace kinstab {
namespace {

// 8-point Gauss-Legendre nodes and weights on [-1, 1] (A&S Table 25.4).
constexpr std::array<double, 4> kNodes = {0.1834346424956498, 0.5255324099163290,
                                          0.7966664774136267, 0.9602898564975363};
constexpr std::array<double, 4> kWeights = {0.3626837833783620, 0.3137066458778873,
                                            0.2223810344533745, 0.1012285362903763};

// Integral over one interval of length h of W(s)^beta, W(s) = w0 + v0 s + dv s^2 / (2h).
double intervalIntegral(double h, double w0, double v0, double dv, double beta) {
    double sum = 0.0;
    for (std::size_t k = 0; k < kNodes.size(); ++k) {
        for (const double sign : {-1.0, 1.0}) {
            const double t = 0.5 * (1.0 + sign * kNodes[k]); // node on [0, 1]
            const double s = h * t * t * t;                  // s = h t^3, ds = 3 h t^2 dt
            const double w = w0 + v0 * s + dv * s * s / (2.0 * h);
            sum += 0.5 * kWeights[k] * std::pow(std::max(w, 0.0), beta) * 3.0 * h * t * t;
        }
    }
    return sum;
}

} // namespace

Eigen::VectorXd cumulativeWork(const Eigen::VectorXd& delta, const Eigen::VectorXd& shear) {
    Eigen::VectorXd w = Eigen::VectorXd::Zero(delta.size());
    for (Eigen::Index i = 1; i < delta.size(); ++i)
        w(i) = w(i - 1) + 0.5 * (shear(i - 1) + shear(i)) * (delta(i) - delta(i - 1));
    return w;
}

Eigen::VectorXd workAbscissa(const Eigen::VectorXd& delta, const Eigen::VectorXd& shear,
                             double beta) {
    if (beta == 0.0) return delta.array() - delta(0);
    const Eigen::VectorXd w = cumulativeWork(delta, shear);
    Eigen::VectorXd xi = Eigen::VectorXd::Zero(delta.size());
    for (Eigen::Index i = 1; i < delta.size(); ++i) {
        const double h = delta(i) - delta(i - 1);
        xi(i) =
            xi(i - 1) + intervalIntegral(h, w(i - 1), shear(i - 1), shear(i) - shear(i - 1), beta);
    }
    return xi;
}

} // namespace kinstab
