// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Brent's bracketed 1-D minimization (golden section safeguarded by parabolic interpolation).
// Source: R. P. Brent, "Algorithms for Minimization without Derivatives" (1973), ch. 5,
// procedure localmin. Used by the friction-law fit to find V_inf (Furgerson 1980, Eq. 5).

#include <cmath>
#include <limits>

namespace kinstab {

struct MinimumResult {
    double x = std::numeric_limits<double>::quiet_NaN();
    double fx = std::numeric_limits<double>::quiet_NaN();
    int evaluations = 0;
    bool converged = false;
};

// Local minimum of f on [a, b] (a < b), located to within about 2 (sqrt(eps) |x| + tol/3)
// (Brent's stopping rule, eps the machine epsilon). f is never
// evaluated at a or b themselves: callers compare the end points when a minimum may sit there.
template <class F>
MinimumResult brentMinimize(F&& f, double a, double b, double tol = 1e-10,
                            int maxIterations = 200) {
    const double golden = 0.5 * (3.0 - std::sqrt(5.0));
    const double eps = std::sqrt(std::numeric_limits<double>::epsilon());
    double x = a + golden * (b - a), w = x, v = x;
    double fx = f(x), fw = fx, fv = fx;
    double d = 0.0, e = 0.0;
    MinimumResult r;
    r.evaluations = 1;
    for (int it = 0; it < maxIterations; ++it) {
        const double m = 0.5 * (a + b);
        const double tol1 = eps * std::abs(x) + tol / 3.0;
        const double tol2 = 2.0 * tol1;
        if (std::abs(x - m) <= tol2 - 0.5 * (b - a)) {
            r.converged = true;
            break;
        }
        bool golden_step = true;
        if (std::abs(e) > tol1) { // try a parabola through x, w, v
            double rr = (x - w) * (fx - fv);
            double q = (x - v) * (fx - fw);
            double p = (x - v) * q - (x - w) * rr;
            q = 2.0 * (q - rr);
            if (q > 0.0)
                p = -p;
            else
                q = -q;
            if (std::abs(p) < std::abs(0.5 * q * e) && p > q * (a - x) && p < q * (b - x)) {
                e = d;
                d = p / q;
                const double u = x + d;
                if (u - a < tol2 || b - u < tol2) d = (x < m) ? tol1 : -tol1;
                golden_step = false;
            }
        }
        if (golden_step) {
            e = (x < m) ? b - x : a - x;
            d = golden * e;
        }
        const double u = std::abs(d) >= tol1 ? x + d : x + (d > 0.0 ? tol1 : -tol1);
        const double fu = f(u);
        ++r.evaluations;
        if (fu <= fx) {
            if (u < x)
                b = x;
            else
                a = x;
            v = w, fv = fw, w = x, fw = fx, x = u, fx = fu;
        } else {
            if (u < x)
                a = u;
            else
                b = u;
            if (fu <= fw || w == x) {
                v = w, fv = fw, w = u, fw = fu;
            } else if (fu <= fv || v == x || v == w) {
                v = u, fv = fu;
            }
        }
    }
    r.x = x;
    r.fx = fx;
    return r;
}

} // namespace kinstab
