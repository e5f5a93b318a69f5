// SPDX-License-Identifier: GPL-3.0-or-later
// The extrema of the displacement inside an accepted planar step, on the step's interpolant.
#include "core/slab/PlanarRun.h"

namespace kinstab::planar {

namespace {

// Bisection on the step's fraction: 60 halvings or a width of 1e-16 reach the rounding of a
// fraction in [0, 1].
constexpr int kBisections = 60;
constexpr double kFractionResolution = 1e-16;

// Where slope(x), of sign `start` at x = 0 and of the other at 1, changes sign: bisection.
double signChangeOnStep(auto&& slope, double start) {
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < kBisections && hi - lo > kFractionResolution; ++i) {
        const double mid = 0.5 * (lo + hi);
        slope(mid)* start > 0.0 ? lo = mid : hi = mid;
    }
    return 0.5 * (lo + hi);
}

// Where a velocity component changes sign inside a step of length h from y0 to y1, the
// extremum of the cubic Hermite interpolant of that displacement (error O(h^4)).
std::optional<Extremum> hermiteExtremum(double h, const Vec4& y0, const Vec4& y1, int c) {
    const double p0 = y0[c], p1 = y1[c], m0 = h * y0[c + 2], m1 = h * y1[c + 2];
    if (!(m0 * m1 < 0.0)) return std::nullopt;
    // p'(s) = a s^2 + b s + m0 on [0, 1] changes sign once.
    const double a = 6.0 * (p0 - p1) + 3.0 * (m0 + m1), b = 6.0 * (p1 - p0) - 4.0 * m0 - 2.0 * m1;
    const double t = signChangeOnStep([&](double x) { return (a * x + b) * x + m0; }, m0),
                 t2 = t * t, t3 = t2 * t;
    return Extremum{(2 * t3 - 3 * t2 + 1) * p0 + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * p1 +
                        (t3 - t2) * m1,
                    t};
}

// The same from an implicit step's collocation polynomial (error O(h^6)): the cubic's O(h^4)
// had moved the peaks by up to 5e-7 relative once the implicit steps grew longer.
std::optional<Extremum> collocationExtremum(const SlipRadauPolynomial& p, const Vec4& y0,
                                            const Vec4& y1, int c) {
    const double u0 = y0[c + 2];
    if (!(u0 * y1[c + 2] < 0.0)) return std::nullopt;
    const double x = signChangeOnStep([&](double xx) { return p.at(xx)[c]; }, u0);
    return Extremum{y0[c] + p.displacement(x)[c], x};
}

} // namespace

StepExtrema stepExtrema(double h, const Vec4& y0, const Vec4& y1, const SlipRadauPolynomial& p) {
    if (p.h > 0.0) return {collocationExtremum(p, y0, y1, 0), collocationExtremum(p, y0, y1, 1)};
    return {hermiteExtremum(h, y0, y1, 0), hermiteExtremum(h, y0, y1, 1)};
}

} // namespace kinstab::planar
