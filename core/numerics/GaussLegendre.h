// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// 10-point Gauss-Legendre quadrature (Abramowitz & Stegun, Table 25.4): exact for polynomials
// of degree 19, so on a piece much shorter than the sine's period it integrates the smooth
// accelerations of this project to rounding.

#include <array>
#include <cstddef>

namespace kinstab {

inline constexpr std::array<double, 5> kGaussLegendre10Nodes = {
    0.1488743389816312, 0.4333953941292472, 0.6794095682990244, 0.8650633666889845,
    0.9739065285171717};
inline constexpr std::array<double, 5> kGaussLegendre10Weights = {
    0.2955242247147529, 0.2692667193099963, 0.2190863625159820, 0.1494513491505806,
    0.0666713443086881};

// Integral of f over [lo, hi].
template <class F> double gaussLegendre10(F&& f, double lo, double hi) {
    const double m = 0.5 * (lo + hi), r = 0.5 * (hi - lo);
    double sum = 0.0;
    for (std::size_t i = 0; i < kGaussLegendre10Nodes.size(); ++i)
        sum += kGaussLegendre10Weights[i] *
               (f(m - r * kGaussLegendre10Nodes[i]) + f(m + r * kGaussLegendre10Nodes[i]));
    return r * sum;
}

} // namespace kinstab
