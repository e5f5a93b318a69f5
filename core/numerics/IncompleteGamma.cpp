// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/numerics/IncompleteGamma.h"

#include <cmath>
#include <limits>

namespace kinstab {
namespace {

double lowerGammaSeries(double a, double x) {
    double term = 1.0 / a;
    double sum = term;
    for (int n = 1; n <= 10000; ++n) {
        term *= x / (a + n);
        sum += term;
        if (std::abs(term) < std::abs(sum) * 1e-16) break;
    }
    return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

double upperGammaContinuedFraction(double a, double x) {
    constexpr double tiny = 1e-300;
    double b = x + 1.0 - a;
    double c = 1.0 / tiny;
    double d = 1.0 / b;
    double h = d;
    for (int i = 1; i <= 10000; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::abs(d) < tiny) d = tiny;
        c = b + an / c;
        if (std::abs(c) < tiny) c = tiny;
        d = 1.0 / d;
        const double del = d * c;
        h *= del;
        if (std::abs(del - 1.0) < 1e-16) break;
    }
    return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

} // namespace

double regularizedLowerGamma(double a, double x) {
    if (!(a > 0.0) || !(x >= 0.0) || std::isnan(x)) return std::numeric_limits<double>::quiet_NaN();
    if (x == 0.0) return 0.0;
    if (std::isinf(x)) return 1.0;
    if (x < a + 1.0) return lowerGammaSeries(a, x);
    return 1.0 - upperGammaContinuedFraction(a, x);
}

} // namespace kinstab
