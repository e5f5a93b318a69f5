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

// fdf(t, f, df) evaluates f and f'. Appends the roots in (lo, hi] in increasing order; with
// `from` in [lo, hi], only those of the sub-intervals that end after it (the sub-intervals stay
// those of [lo, hi], so every root reported is the one the whole scan would report, to the bit).
template <class FDF>
void levelCrossings(FDF&& fdf, double lo, double hi, int subIntervals, std::vector<double>& out,
                    CrossingScanWork& work, double from = -INFINITY) {
    auto root = [&](double a, double b, double fa, double fb) {
        const RootResult r = safeguardedNewton(fdf, a, b, fa, fb);
        work.iterations += r.iterations;
        return std::clamp(r.x, a, b);
    };
    auto slopeAt = [&](double t) {
        double f = 0, df = 0;
        fdf(t, f, df);
        ++work.evaluations;
        return df;
    };
    auto point = [&](int i) { return i == subIntervals ? hi : lo + (hi - lo) * i / subIntervals; };
    int first = 1;
    while (first < subIntervals && !(point(first) > from))
        ++first;
    double t0 = first == 1 ? lo : point(first - 1), f0 = 0, d0 = 0;
    fdf(t0, f0, d0);
    ++work.evaluations;
    for (int i = first; i <= subIntervals; ++i) {
        const double t1 = point(i);
        double f1 = 0, d1 = 0;
        fdf(t1, f1, d1);
        ++work.evaluations;
        if ((f0 < 0.0 && f1 >= 0.0) || (f0 > 0.0 && f1 <= 0.0)) {
            out.push_back(root(t0, t1, f0, f1));
        } else if (f0 != 0.0 && (f0 < 0.0) == (f1 < 0.0)) {
            const double s = f0 < 0.0 ? 1.0 : -1.0; // s f < 0 at both ends
            if (s * d0 > 0.0 && s * d1 < 0.0) {
                // Interior extremum of s f: bisect on the slope.
                double a = t0, b = t1;
                for (int k = 0; k < 200 && b - a > 1e-14 * std::max(1.0, std::abs(b)); ++k) {
                    const double m = 0.5 * (a + b);
                    if (s * slopeAt(m) > 0.0)
                        a = m;
                    else
                        b = m;
                    ++work.iterations;
                }
                const double m = 0.5 * (a + b);
                double fm = 0, dm = 0;
                fdf(m, fm, dm);
                ++work.evaluations;
                if (s * fm > 0.0) {
                    out.push_back(root(t0, m, f0, fm));
                    out.push_back(root(m, t1, fm, f1));
                }
            }
        }
        t0 = t1;
        f0 = f1;
        d0 = d1;
    }
}

} // namespace kinstab
