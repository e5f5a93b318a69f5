#!/usr/bin/env python3
# SPDX-License-Identifier: GPL-3.0-or-later
"""Coefficients of the s-stage Radau IIA method and of its embedded error estimate, to 21 digits
(the constants of core/numerics/RadauIIA.h; needs Debian's python3-mpmath).

usage: radau-coefficients.py [STAGES]   (default 5)

- nodes c: the roots of d^(s-1)/dx^(s-1) [x^(s-1) (x - 1)^s] (Hairer & Wanner II, §IV.5);
- A: a_ij = integral from 0 to c_i of the Lagrange polynomial l_j on the nodes (collocation);
- u1: the real eigenvalue of A^-1;
- d: the estimate's weights. The embedded formula y^ = y0 + h (g0 f(t0, y0) + sum b^_i f(Y_i)),
  g0 = 1/u1, has order s: sum_i b^_i c_i^(k-1) + g0 [k = 1] = 1/k for k = 1..s. With
  h f(Y_i) = sum_j (A^-1)_ij Z_j, y1 - y^ = -h g0 (f(t0, y0) + sum_j d_j Z_j / h) where
  d_j = -u1 sum_i (b_i - b^_i) (A^-1)_ij. For s = 3 this gives RADAU5's d = (-(13 + 7 sqrt 6)/3,
  (-13 + 7 sqrt 6)/3, -1/3), the check that the construction is the published one.
"""

import sys
from math import comb

import mpmath as mp

mp.mp.dps = 40


def radau(s):
    # x^(s-1) (x - 1)^s by degree, differentiated s - 1 times.
    p = [mp.mpf(0)] * (2 * s)
    for k in range(s + 1):
        p[s - 1 + k] += comb(s, k) * (-1) ** (s - k)
    for _ in range(s - 1):
        p = [p[i] * i for i in range(1, len(p))]
    c = sorted(mp.re(r) for r in mp.polyroots(list(reversed(p)), maxsteps=200, extraprec=200))

    def lagrange_integral(j, upper):
        poly, den = [mp.mpf(1)], mp.mpf(1)
        for m in range(s):
            if m == j:
                continue
            poly = [(poly[i - 1] if i > 0 else 0) - c[m] * (poly[i] if i < len(poly) else 0)
                    for i in range(len(poly) + 1)]
            den *= c[j] - c[m]
        return sum(poly[i] * upper ** (i + 1) / (i + 1) for i in range(len(poly))) / den

    a = mp.matrix(s, s)
    for i in range(s):
        for j in range(s):
            a[i, j] = lagrange_integral(j, c[i])
    w = a ** -1
    u1 = [mp.re(e) for e in mp.eig(w)[0] if abs(mp.im(e)) < mp.mpf(10) ** -20][0]
    g0 = 1 / u1
    v, r = mp.matrix(s, s), mp.matrix(s, 1)
    for k in range(1, s + 1):
        for i in range(s):
            v[k - 1, i] = c[i] ** (k - 1)
        r[k - 1] = mp.mpf(1) / k - (g0 if k == 1 else 0)
    bhat = mp.lu_solve(v, r)
    b = [a[s - 1, j] for j in range(s)]
    d = [-u1 * sum((b[i] - bhat[i]) * w[i, j] for i in range(s)) for j in range(s)]
    return c, a, u1, d


def main():
    s = int(sys.argv[1]) if len(sys.argv) > 1 else 5
    c, a, u1, d = radau(s)
    text = lambda x: mp.nstr(x, 21, min_fixed=-30, max_fixed=30)
    print("c  =", ", ".join(text(x) for x in c))
    for i in range(s):
        print(f"A[{i}] =", ", ".join(text(a[i, j]) for j in range(s)))
    print("u1 =", text(u1))
    print("d  =", ", ".join(text(x) for x in d))


if __name__ == "__main__":
    main()
