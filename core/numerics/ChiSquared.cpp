// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/numerics/ChiSquared.h"

#include "core/numerics/IncompleteGamma.h"
#include "core/numerics/RootFinding.h"

#include <cmath>
#include <limits>

namespace kinstab {

double chiSquaredPdf(double x, double k) {
    if (x <= 0.0) return 0.0;
    const double h = 0.5 * k;
    return std::exp((h - 1.0) * std::log(x) - 0.5 * x - h * std::log(2.0) - std::lgamma(h));
}

double chiSquaredCdf(double x, double k) {
    if (std::isnan(x) || !(k > 0.0)) return std::numeric_limits<double>::quiet_NaN();
    if (x <= 0.0) return 0.0;
    return regularizedLowerGamma(0.5 * k, 0.5 * x);
}

double chiSquaredQuantile(double p, double k) {
    if (!(p > 0.0) || !(p < 1.0) || !(k > 0.0)) return std::numeric_limits<double>::quiet_NaN();
    double hi = std::max(1.0, k);
    while (chiSquaredCdf(hi, k) < p && hi < 1e300)
        hi *= 2.0;
    auto fdf = [k, p](double x, double& f, double& df) {
        f = chiSquaredCdf(x, k) - p;
        df = chiSquaredPdf(x, k);
    };
    return safeguardedNewton(fdf, 0.0, hi, -p, chiSquaredCdf(hi, k) - p).x;
}

} // namespace kinstab
