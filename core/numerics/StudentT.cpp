// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/numerics/StudentT.h"

#include "core/numerics/IncompleteBeta.h"
#include "core/numerics/RootFinding.h"

#include <cmath>
#include <limits>

namespace kinstab {

double studentTPdf(double t, double nu) {
    const double logc =
        std::lgamma(0.5 * (nu + 1.0)) - std::lgamma(0.5 * nu) - 0.5 * std::log(nu * M_PI);
    return std::exp(logc - 0.5 * (nu + 1.0) * std::log1p(t * t / nu));
}

double studentTCdf(double t, double nu) {
    if (std::isnan(t) || !(nu > 0.0)) return std::numeric_limits<double>::quiet_NaN();
    const double tail = 0.5 * regularizedIncompleteBeta(0.5 * nu, 0.5, nu / (nu + t * t));
    return t >= 0.0 ? 1.0 - tail : tail;
}

double studentTQuantile(double p, double nu) {
    if (!(p > 0.0) || !(p < 1.0) || !(nu > 0.0)) return std::numeric_limits<double>::quiet_NaN();
    if (p == 0.5) return 0.0;
    if (p < 0.5) return -studentTQuantile(1.0 - p, nu); // symmetry keeps precision in the tail
    double hi = 1.0;
    while (studentTCdf(hi, nu) < p && hi < 1e300)
        hi *= 2.0;
    auto fdf = [nu, p](double t, double& f, double& df) {
        f = studentTCdf(t, nu) - p;
        df = studentTPdf(t, nu);
    };
    return safeguardedNewton(fdf, 0.0, hi, 0.5 - p, studentTCdf(hi, nu) - p).x;
}

} // namespace kinstab
