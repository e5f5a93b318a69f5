// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Brent's bracketed 1-D minimization (golden section safeguarded by parabolic interpolation).
// Source: R. P. Brent, "Algorithms for Minimization without Derivatives" (1973), ch. 5,
// procedure localmin. Used by the friction-law fit to find V_inf (Furgerson 1980, Eq. 5).

#include <cmath>
#include <limits>
#include <optional>

namespace kinstab {

struct MinimumResult {
    double x = std::numeric_limits<double>::quiet_NaN();
    double fx = std::numeric_limits<double>::quiet_NaN();
    int evaluations = 0;
    bool converged = false;
};

namespace brent {

// localmin's bracket [a, b] and its three best points: x the least f so far, w the second,
// v the previous w.
struct Points {
    double a, b;
    double x, w, v;
    double fx, fw, fv;
};

// The step to the minimum of the parabola through x, w, v, when it falls inside the bracket and
// is shorter than half the step before last (e); kept tol1 inside the ends. nullopt: a golden
// section step instead.
inline std::optional<double> parabolicStep(const Points& s, double e, double m, double tol1,
                                           double tol2) {
    double rr = (s.x - s.w) * (s.fx - s.fv);
    double q = (s.x - s.v) * (s.fx - s.fw);
    double p = (s.x - s.v) * q - (s.x - s.w) * rr;
    q = 2.0 * (q - rr);
    if (q > 0.0)
        p = -p;
    else
        q = -q;
    if (!(std::abs(p) < std::abs(0.5 * q * e) && p > q * (s.a - s.x) && p < q * (s.b - s.x)))
        return std::nullopt;
    const double d = p / q;
    const double u = s.x + d;
    if (u - s.a < tol2 || s.b - u < tol2) return (s.x < m) ? tol1 : -tol1;
    return d;
}

// f(u) = fu is known: the bracket shrinks to the side of x or u that holds the minimum, and
// x, w, v move down the ranking.
inline void takePoint(Points& s, double u, double fu) {
    if (fu <= s.fx) {
        if (u < s.x)
            s.b = s.x;
        else
            s.a = s.x;
        s.v = s.w, s.fv = s.fw, s.w = s.x, s.fw = s.fx, s.x = u, s.fx = fu;
        return;
    }
    if (u < s.x)
        s.a = u;
    else
        s.b = u;
    if (fu <= s.fw || s.w == s.x) {
        s.v = s.w, s.fv = s.fw, s.w = u, s.fw = fu;
    } else if (fu <= s.fv || s.v == s.x || s.v == s.w) {
        s.v = u, s.fv = fu;
    }
}

} // namespace brent

// Local minimum of f on [a, b] (a < b), located to within about 2 (sqrt(eps) |x| + tol/3)
// (Brent's stopping rule, eps the machine epsilon). f is never
// evaluated at a or b themselves: callers compare the end points when a minimum may sit there.
template <class F>
MinimumResult brentMinimize(F&& f, double a, double b, double tol = 1e-10,
                            int maxIterations = 200) {
    const double golden = 0.5 * (3.0 - std::sqrt(5.0));
    const double eps = std::sqrt(std::numeric_limits<double>::epsilon());
    const double x0 = a + golden * (b - a), f0 = f(x0);
    brent::Points s{a, b, x0, x0, x0, f0, f0, f0};
    double d = 0.0, e = 0.0;
    MinimumResult r;
    r.evaluations = 1;
    for (int it = 0; it < maxIterations; ++it) {
        const double m = 0.5 * (s.a + s.b);
        const double tol1 = eps * std::abs(s.x) + tol / 3.0;
        const double tol2 = 2.0 * tol1;
        if (std::abs(s.x - m) <= tol2 - 0.5 * (s.b - s.a)) {
            r.converged = true;
            break;
        }
        const std::optional<double> parabola =
            std::abs(e) > tol1 ? brent::parabolicStep(s, e, m, tol1, tol2) : std::nullopt;
        if (parabola) {
            e = d;
            d = *parabola;
        } else {
            e = (s.x < m) ? s.b - s.x : s.a - s.x;
            d = golden * e;
        }
        const double u = std::abs(d) >= tol1 ? s.x + d : s.x + (d > 0.0 ? tol1 : -tol1);
        const double fu = f(u);
        ++r.evaluations;
        brent::takePoint(s, u, fu);
    }
    r.x = s.x;
    r.fx = s.fx;
    return r;
}

} // namespace kinstab
