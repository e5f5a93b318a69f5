// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Integrals of the enveloped sine's shape g(s) = (exp(-p s) - exp(-q s)) sin(w s), 0 <= p < q,
// over [t0, t0 + h], in closed form and free of cancellation (docs/theory.md §6.2 "numerical
// hygiene"; §4 row 12):
//  - a short span h (grazing slips last microseconds): the increments are formed from the
//    phi-functions phi_k(z h) by their Taylor series, not as a difference of primitives;
//  - q close to p (A / S_max is then huge, ~1/(q - p)): the two exponentials are never
//    subtracted; their difference is carried as expm1((q - p) s) and divided differences.
// With z_l = -l + i w, g(s) = Im(exp(z_p s) - exp(z_q s)) and d = q - p = z_p - z_q.

#include <complex>
#include <limits>

namespace kinstab {

// g and its first two derivatives at one time.
struct ShapeAt {
    double g = 0, dg = 0, d2g = 0;
};

class DecaySineIntegrals {
public:
    DecaySineIntegrals(double p, double q, double omega);

    // int_{t0}^{t0+h} g(s) ds; with valueAtEnd, also g(t0 + h) from the same exponentials.
    double first(double t0, double h, double* valueAtEnd = nullptr) const;
    // first(t0, h), with g, g' and g'' at t0 + h from the same exponentials (g as first() gives
    // it): the stop search's Halley steps (docs/theory.md §6.3).
    double firstWithShape(double t0, double h, ShapeAt& end) const;
    // int_{t0}^{t0+h} (t0 + h - s) g(s) ds  (the second integral of g from t0)
    double second(double t0, double h) const;
    // first(t0, h), with second(t0, h) in secondOut, from one set of exponentials; with
    // valueAtEnd, also g(t0 + h) as first() gives it.
    double both(double t0, double h, double& secondOut, double* valueAtEnd = nullptr) const;

private:
    using Complex = std::complex<double>;
    struct Point {
        double t = std::numeric_limits<double>::quiet_NaN();
        bool near = true; // d t < 1: exp(z_p t) is carried as exp(z_q t) (1 + em1)
        double em1 = 0;   // expm1(d t) when near
        Complex eq, ep;   // exp(z_q t); exp(z_p t) when not near
        Complex p1, p2;   // primitives of exp(z_p s) - exp(z_q s): exp(z s)/z, exp(z s)/z^2
    };
    void pointAt(double t, Point& out) const;
    // The last origin and the last long span's end, per thread (see origin()).
    struct Memo {
        double p = -1, q = -1, omega = -1;
        Point origin, end;
    };
    Memo& memo() const;
    const Point& origin(Memo& m, double t0) const;
    const Point& endAt(Memo& m, double t) const; // pointAt(t), kept as a possible next origin
    // The phi-series' sums over a short span h: phi_k and the divided sums of k = 1 (and of
    // k = 2 with second), sum D_n / n! and exp(w_p).
    struct Series {
        Complex phi[2], div[2], expDiv, expP;
    };
    Series series(double h, bool second) const;
    Complex increment(const Point& o, double dh, double hk, Complex phi, Complex div) const;
    // The first integral over a short span from o.t; with second also the second, with end
    // exp(z_p (t0+h)) - exp(z_q (t0+h)), and with endQ exp(z_q (t0+h)).
    Complex shortSpan(const Point& o, double h, Complex* second = nullptr, Complex* end = nullptr,
                      Complex* endQ = nullptr) const;
    // g, g', g'' from diff = exp(z_p t) - exp(z_q t) and eq = exp(z_q t).
    ShapeAt shapeFrom(Complex diff, Complex eq) const;

    double p_, q_, d_, omega_;
    double zqAbs_; // |z_q|: spans with |z_q| h <= 1/2 are short
    Complex zp_, zq_;
    Complex inv_p_, inv_q_, inv_pq_; // 1/z_p, 1/z_q, 1/(z_p z_q)
};

} // namespace kinstab
