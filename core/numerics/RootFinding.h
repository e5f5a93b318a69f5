// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Safeguarded root finding on a bracket. Every event of the slab model is located here.
// Bare Newton diverges at grazing events (f' -> 0 at a double root), so each Newton step
// is accepted only when it stays inside the shrinking bracket; otherwise we bisect.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>

namespace kinstab {

struct RootResult {
    double x = std::numeric_limits<double>::quiet_NaN();
    int iterations = 0;
    bool converged = false;
};

namespace rootstop {

// The answer without a step: an end that is a root, or no sign change (not converged).
inline std::optional<RootResult> withoutStep(double lo, double hi, double flo, double fhi) {
    if (flo == 0.0) return RootResult{lo, 0, true};
    if (fhi == 0.0) return RootResult{hi, 0, true};
    if ((flo > 0.0) == (fhi > 0.0)) return RootResult{}; // no bracket
    return std::nullopt;
}

// The bracket oriented so that f(a) < 0 < f(b), and the first point: start when it lies
// inside, else the midpoint.
struct Opening {
    double a, b, x;
};
inline Opening opening(double lo, double hi, double flo, double start) {
    Opening o{lo, hi, 0.5 * (lo + hi)};
    if (flo > 0.0) std::swap(o.a, o.b);
    if (start > std::min(lo, hi) && start < std::max(lo, hi)) o.x = start;
    return o;
}

// Once Newton converges quadratically (a step under 1/100 of the one before), the error left
// after a step is about (step / previous step)^2 x step. Two Newton steps in a row are needed
// to see the rate (lastNewton is inf after the start or a bisection, and then the ratio is 0,
// not small). Updates lastNewton to this step.
inline double newtonPredictedError(double dx, double& lastNewton) {
    const double ratio = std::abs(dx) / lastNewton;
    lastNewton = std::abs(dx);
    return ratio > 0.0 && ratio < 0.01 ? ratio * ratio * std::abs(dx)
                                       : std::numeric_limits<double>::infinity();
}

// Done when the bracket [a, b], the last step dx or the predicted error is below the tolerance
// (absTolerance, or a few ulps of the bracket's ends).
inline bool converged(double a, double b, double dx, double predictedError, double absTolerance) {
    const double tol = std::max(absTolerance, 4.0 * std::numeric_limits<double>::epsilon() *
                                                  std::max({std::abs(a), std::abs(b), 1e-300}));
    return std::abs(b - a) <= tol || std::abs(dx) <= 0.25 * tol || predictedError <= 0.25 * tol;
}

// A corrector's step from x and the error it predicts it leaves.
struct Step {
    double dx, predictedError;
};

// Newton's step, the fallback of every corrector (updates lastNewton, see newtonPredictedError).
inline Step newtonStep(double f, double df, double& lastNewton) {
    const double dx = f / df;
    return {dx, newtonPredictedError(dx, lastNewton)};
}

// The iteration Newton and Halley share: eval(x, v) fills v (v.f, v.df and what the corrector
// reads); the bracket [a, b] shrinks around each point; the corrector's step
// correct(v, a, b, x, lastNewton) is taken where Newton's would stay inside the bracket and
// shrink it fast enough, else the bracket is bisected.
template <class Values, class Eval, class Correct>
RootResult iterate(Eval&& eval, Correct&& correct, double lo, double hi, double flo, double start,
                   int maxIterations, double absTolerance) {
    constexpr double inf = std::numeric_limits<double>::infinity();
    RootResult r;
    auto [a, b, x] = opening(lo, hi, flo, start);
    double dxOld = std::abs(hi - lo), dx = dxOld, lastNewton = inf, predictedError = inf;
    Values v;
    eval(x, v);
    for (r.iterations = 1; r.iterations <= maxIterations; ++r.iterations) {
        if (v.f == 0.0) return {x, r.iterations, true};
        if (v.f < 0.0)
            a = x;
        else
            b = x;
        const double f = v.f, df = v.df;
        const bool newtonOutside = ((x - b) * df - f) * ((x - a) * df - f) > 0.0;
        const bool newtonSlow = std::abs(2.0 * f) > std::abs(dxOld * df);
        dxOld = dx;
        if (newtonOutside || newtonSlow || df == 0.0) {
            dx = 0.5 * (b - a);
            x = a + dx;
            lastNewton = predictedError = inf;
        } else {
            const Step step = correct(v, a, b, x, lastNewton);
            dx = step.dx;
            x -= dx;
            predictedError = step.predictedError;
        }
        if (converged(a, b, dx, predictedError, absTolerance)) {
            r.x = x;
            r.converged = true;
            return r;
        }
        eval(x, v);
    }
    r.x = x;
    return r;
}

} // namespace rootstop

// Root of f on [lo, hi] where f(lo) and f(hi) differ in sign (or one is zero).
// fdf(x, f, df) evaluates the function and its derivative. Stops when the bracket is a few
// ulps wide, so the answer is as exact as double arithmetic allows.
// start: a first guess inside the bracket (the midpoint when absent or outside); a good one
// saves the bisection steps before Newton takes over. absTolerance: stop once the bracket or
// the Newton step is below it (0: a few ulps, as exact as double arithmetic allows).
// Once Newton converges quadratically (a step under 1/100 of the one before), the error left
// after a step is about (step / previous step)^2 x step: when that is below the tolerance, the
// point is returned without the evaluation that would only confirm it. At a double root Newton
// is linear (each step about half the last) and this never fires.
template <class FDF>
RootResult safeguardedNewton(FDF&& fdf, double lo, double hi, double flo, double fhi,
                             int maxIterations = 200,
                             double start = std::numeric_limits<double>::quiet_NaN(),
                             double absTolerance = 0.0) {
    if (const auto done = rootstop::withoutStep(lo, hi, flo, fhi)) return *done;
    struct Values {
        double f = 0.0, df = 0.0;
    };
    return rootstop::iterate<Values>(
        [&](double x, Values& v) { fdf(x, v.f, v.df); },
        [](const Values& v, double, double, double, double& lastNewton) {
            return rootstop::newtonStep(v.f, v.df, lastNewton);
        },
        lo, hi, flo, start, maxIterations, absTolerance);
}

// A first guess for a root on [lo, hi] from the values and slopes at both ends: the root of
// their cubic Hermite interpolant (fourth-order accurate where the secant is second-order).
// f(lo) and f(hi) must differ in sign.
inline double hermiteRootGuess(double lo, double hi, double flo, double fhi, double dflo,
                               double dfhi) {
    const double h = hi - lo, dlo = h * dflo, dhi = h * dfhi;
    // p(u) = c0 + c1 u + c2 u^2 + c3 u^3 on [0, 1], p(0) = flo, p(1) = fhi.
    const double c0 = flo, c1 = dlo, c2 = 3.0 * (fhi - flo) - 2.0 * dlo - dhi,
                 c3 = 2.0 * (flo - fhi) + dlo + dhi;
    auto cubic = [&](double u, double& f, double& df) {
        f = c0 + u * (c1 + u * (c2 + u * c3));
        df = c1 + u * (2.0 * c2 + u * 3.0 * c3);
    };
    const double secant = flo / (flo - fhi);
    const RootResult u = safeguardedNewton(cubic, 0.0, 1.0, flo, fhi, 60, secant, 1e-12);
    return lo + h * (std::isfinite(u.x) ? u.x : secant);
}

} // namespace kinstab
