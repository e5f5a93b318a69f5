// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// All sign changes of a smooth function of time on an interval, found on sub-intervals short
// enough to hold at most one interior extremum (the caller picks them from the time scales of
// its inputs; docs/theory.md §6.3 last item). In each sub-interval:
//  - a sign change at the ends gives one root, located by safeguarded Newton;
//  - equal signs with the slope pointing toward zero at one end and away at the other mean an
//    interior extremum; it is found as the root of f' by bisection and, when it crosses zero,
//    gives the two roots around it. A touch without crossing is not a crossing.

#include "core/numerics/RootFinding.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace kinstab {

struct CrossingScanWork {
    long evaluations = 0;
    long iterations = 0;
};

namespace crossingscan {

// f and f' at t.
struct Point {
    double t = 0, f = 0, df = 0;
};

template <class FDF> Point evaluate(FDF& fdf, double t, CrossingScanWork& work) {
    Point p{t, 0, 0};
    fdf(t, p.f, p.df);
    ++work.evaluations;
    return p;
}

// The root between a and b (f changes sign), by safeguarded Newton, kept inside [a, b].
template <class FDF>
double root(FDF& fdf, double a, double b, double fa, double fb, CrossingScanWork& work) {
    const RootResult r = safeguardedNewton(fdf, a, b, fa, fb);
    work.iterations += r.iterations;
    return std::clamp(r.x, a, b);
}

// The extremum of s f inside (a, b), where s f' > 0 at a and < 0 at b: bisection on the slope.
template <class FDF>
double extremum(FDF& fdf, double a, double b, double s, CrossingScanWork& work) {
    for (int k = 0; k < 200 && b - a > 1e-14 * std::max(1.0, std::abs(b)); ++k) {
        const double m = 0.5 * (a + b);
        if (s * evaluate(fdf, m, work).df > 0.0)
            a = m;
        else
            b = m;
        ++work.iterations;
    }
    return 0.5 * (a + b);
}

// The crossings inside the sub-interval from p0 to p1, appended in increasing order.
template <class FDF>
void crossingsIn(FDF& fdf, const Point& p0, const Point& p1, std::vector<double>& out,
                 CrossingScanWork& work) {
    const double f0 = p0.f, f1 = p1.f;
    if ((f0 < 0.0 && f1 >= 0.0) || (f0 > 0.0 && f1 <= 0.0)) {
        out.push_back(root(fdf, p0.t, p1.t, f0, f1, work));
        return;
    }
    if (f0 == 0.0 || (f0 < 0.0) != (f1 < 0.0)) return;
    const double s = f0 < 0.0 ? 1.0 : -1.0; // s f < 0 at both ends
    if (!(s * p0.df > 0.0 && s * p1.df < 0.0)) return;
    // Interior extremum of s f: two crossings around it when it reaches past zero.
    const Point m = evaluate(fdf, extremum(fdf, p0.t, p1.t, s, work), work);
    if (s * m.f > 0.0) {
        out.push_back(root(fdf, p0.t, m.t, f0, m.f, work));
        out.push_back(root(fdf, m.t, p1.t, m.f, f1, work));
    }
}

} // namespace crossingscan

// fdf(t, f, df) evaluates f and f'. Appends the roots in (lo, hi] in increasing order; with
// `from` in [lo, hi], only those of the sub-intervals that end after it (the sub-intervals stay
// those of [lo, hi], so every root reported is the one the whole scan would report, to the bit).
template <class FDF>
void levelCrossings(FDF&& fdf, double lo, double hi, int subIntervals, std::vector<double>& out,
                    CrossingScanWork& work, double from = -INFINITY) {
    auto point = [&](int i) { return i == subIntervals ? hi : lo + (hi - lo) * i / subIntervals; };
    int first = 1;
    while (first < subIntervals && !(point(first) > from))
        ++first;
    crossingscan::Point p0 = crossingscan::evaluate(fdf, first == 1 ? lo : point(first - 1), work);
    for (int i = first; i <= subIntervals; ++i) {
        const crossingscan::Point p1 = crossingscan::evaluate(fdf, point(i), work);
        crossingscan::crossingsIn(fdf, p0, p1, out, work);
        p0 = p1;
    }
}

} // namespace kinstab
