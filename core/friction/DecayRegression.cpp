// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/friction/DecayRegression.h"

#include <cmath>
#include <limits>

namespace kinstab {

DecayLine fitDecayLine(const Eigen::VectorXd& xi, const Eigen::VectorXd& shear, double vInf,
                       double alpha) {
    const Eigen::ArrayXd gap = shear.array() - vInf;
    if (!(gap.minCoeff() > 0.0)) return {};
    const Eigen::ArrayXd eta = std::log(shear(0) - vInf) - gap.log();
    const Eigen::ArrayXd w = gap.pow(alpha);
    const Eigen::ArrayXd x = xi.array();
    const double sw = w.sum(), swx = (w * x).sum(), swe = (w * eta).sum();
    const double swxx = (w * x * x).sum(), swxe = (w * x * eta).sum();
    const double det = sw * swxx - swx * swx;
    if (!(std::abs(det) > 1e-14 * sw * swxx) || !(sw > 0.0)) return {};
    DecayLine line;
    line.c = (sw * swxe - swx * swe) / det;
    line.b = (swe - line.c * swx) / sw;
    line.valid = std::isfinite(line.c) && std::isfinite(line.b);
    return line;
}

Eigen::VectorXd decayModel(const Eigen::VectorXd& xi, double v1, double vInf,
                           const DecayLine& line) {
    return (vInf + (v1 - vInf) * (-(line.c * xi.array() + line.b)).exp()).matrix();
}

double decayMeanSquare(const Eigen::VectorXd& xi, const Eigen::VectorXd& shear, double vInf,
                       double alpha) {
    const DecayLine line = fitDecayLine(xi, shear, vInf, alpha);
    if (!line.valid) return std::numeric_limits<double>::infinity();
    const Eigen::VectorXd r = shear - decayModel(xi, shear(0), vInf, line);
    const double fm = r.squaredNorm() / static_cast<double>(shear.size());
    return std::isfinite(fm) ? fm : std::numeric_limits<double>::infinity();
}

} // namespace kinstab
