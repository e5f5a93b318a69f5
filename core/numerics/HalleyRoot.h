// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Safeguarded Halley iteration on a bracket, for functions whose second and third derivatives
// come from the same evaluation as the value (the closed forms of the exact 1-DOF solver:
// docs/theory.md §6.3). Halley's step converges cubically where Newton's converges
// quadratically, and the third derivative gives the error left after a step from that one
// evaluation, so a root solve from a start within about 1e-5 ends after one evaluation and one
// from within 1e-3 after two, where Newton needs two and three.
//
// With d3f NaN (not known) every step and the stop are safeguardedNewton's
// (core/numerics/RootFinding.h), bit for bit: a piecewise-linear record's a has no useful f''.

#include "core/numerics/RootFinding.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kinstab {

// The value and the first three derivatives at one point.
struct Derivatives {
    double f = 0, df = 0, d2f = 0, d3f = std::numeric_limits<double>::quiet_NaN();
};

namespace halley {
// The error left after a Halley step of length dx from a point where d holds: the step's error
// is about C e^3 with C = (f''/2f')^2 - f'''/(6 f') and e the error before the step, about dx.
// Only valid in the asymptotic range, |f''/f'| |dx| small: infinity outside it.
inline double predictedError(const Derivatives& d, double dx) {
    const double k = d.d2f / (2.0 * d.df);
    if (!(std::abs(k * dx) < 0.01)) return std::numeric_limits<double>::infinity();
    const double c = k * k - d.d3f / (6.0 * d.df);
    // Twice the leading term: dx is the error before the step only to first order.
    return 2.0 * std::abs(c) * std::abs(dx) * dx * dx;
}
// Halley's step from x (Newton's divided by 1 - f f'' / (2 f'^2)) when d3f is known and the
// step lands inside the bracket (a, b) (either order); NaN otherwise (take Newton's then).
inline double halleyStep(const Derivatives& d, double a, double b, double x) {
    if (std::isnan(d.d3f)) return std::numeric_limits<double>::quiet_NaN();
    const double newton = d.f / d.df;
    const double step = newton / (1.0 - 0.5 * newton * d.d2f / d.df);
    const double next = x - step;
    return next > std::min(a, b) && next < std::max(a, b)
               ? step
               : std::numeric_limits<double>::quiet_NaN();
}
} // namespace halley

// Root of f on [lo, hi] where f(lo) and f(hi) differ in sign (or one is zero); fdf(x, d) fills
// d. Same contract as safeguardedNewton: each step is accepted only when it stays inside the
// shrinking bracket and shrinks it fast enough, else the bracket is bisected.
template <class FDF>
RootResult safeguardedHalley(FDF&& fdf, double lo, double hi, double flo, double fhi,
                             int maxIterations = 200,
                             double start = std::numeric_limits<double>::quiet_NaN(),
                             double absTolerance = 0.0) {
    if (const auto done = rootstop::withoutStep(lo, hi, flo, fhi)) return *done;
    return rootstop::iterate<Derivatives>(
        fdf,
        [](const Derivatives& d, double a, double b, double x, double& lastNewton) {
            const double h = halley::halleyStep(d, a, b, x);
            if (std::isnan(h)) return rootstop::newtonStep(d.f, d.df, lastNewton); // as Newton
            return rootstop::Step{h, halley::predictedError(d, h)};
        },
        lo, hi, flo, start, maxIterations, absTolerance);
}

} // namespace kinstab
