// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/numerics/NormalTail.h"

#include <cmath>
#include <numbers>

namespace kinstab {

double normalCdf(double z) {
    return 0.5 * std::erfc(-z / std::numbers::sqrt2);
}

double normalTail(double z) {
    return 0.5 * std::erfc(z / std::numbers::sqrt2);
}

// Below 3, exp(x^2) erfc(x) loses at most 9 ulps to the rounding of x^2. From 3 on, the continued
// fraction erfc(x) = exp(-x^2)/sqrt(pi) * 1/(x + (1/2)/(x + (2/2)/(x + (3/2)/(x + ...)))),
// (Abramowitz & Stegun 7.1.14), evaluated by the modified Lentz method: its terms shrink fast
// enough there that 200 iterations are far more than double precision needs.
double erfcx(double x) {
    if (x < 3.0) return std::exp(x * x) * std::erfc(x);
    constexpr double tiny = 1e-300;
    double f = x, c = x, d = 0.0;
    for (int n = 1; n <= 200; ++n) {
        const double a = 0.5 * n;
        d = x + a * d;
        d = d == 0.0 ? tiny : d;
        c = x + a / c;
        c = c == 0.0 ? tiny : c;
        d = 1.0 / d;
        const double delta = c * d;
        f *= delta;
        if (std::abs(delta - 1.0) < 1e-16) break;
    }
    return 1.0 / (std::sqrt(std::numbers::pi) * f);
}

double millsRatio(double z) {
    return std::sqrt(0.5 * std::numbers::pi) * erfcx(z / std::numbers::sqrt2);
}

double logNormalTail(double z) {
    // ln Q = ln phi(z) + ln R(z), phi(z) = exp(-z^2/2) / sqrt(2 pi).
    return -0.5 * z * z - 0.5 * std::log(2.0 * std::numbers::pi) + std::log(millsRatio(z));
}

} // namespace kinstab
