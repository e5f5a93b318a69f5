// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/excitation/DecaySineIntegrals.h"

#include <cmath>

namespace kinstab {

namespace {
// A span is short when |z_q| h <= 1/4: the phi-series then needs about 11 terms. A longer span
// takes the difference of primitives, which loses at most a factor 1/(|z| h) <= 4 (2 bits) in
// the first integral and (2/(|z| h))^2 <= 64 (6 bits) in the second: harmless at these scales.
constexpr double kShortSpan = 0.25;
constexpr int kSeriesTerms = 24;

// z (re + i im) in plain real arithmetic: std::complex's operator* may go through __muldc3
// (NaN rules) and is slower.
std::complex<double> mul(std::complex<double> z, double re, double im) {
    return {z.real() * re - z.imag() * im, z.real() * im + z.imag() * re};
}
} // namespace

DecaySineIntegrals::DecaySineIntegrals(double p, double q, double omega)
    : p_(p), q_(q), d_(q - p), omega_(omega), zqAbs_(std::hypot(q, omega)), zp_(-p, omega),
      zq_(-q, omega), inv_p_(1.0 / zp_), inv_q_(1.0 / zq_), inv_pq_(inv_p_ * inv_q_) {}

// The exponentials at one time, with one sincos: exp(z_q t), and exp(z_p t) as
// exp(z_q t) (1 + expm1(d t)) when d t < 1 (so that the p - q difference keeps its digits).
void DecaySineIntegrals::pointAt(double t, Point& pt) const {
    pt.t = t;
    const double c = std::cos(omega_ * t), s = std::sin(omega_ * t);
    const double dt = d_ * t;
    pt.near = dt < 1.0;
    if (pt.near) {
        pt.em1 = std::expm1(dt);
        pt.eq = std::exp(-q_ * t) * Complex(c, s);
    } else {
        const double ep = std::exp(-p_ * t);
        pt.ep = ep * Complex(c, s);
        pt.eq = ep * std::exp(-dt) * Complex(c, s);
    }
    // exp(z_p t)/z_p - exp(z_q t)/z_q = exp(z_q t) (z_q expm1(d t) - d) / (z_p z_q): for small d
    // the direct difference cancels, this form has none (-q expm1(d t) - d is one-signed).
    // exp(z_p t)/z_p^2 - exp(z_q t)/z_q^2 = exp(z_q t) (z_q^2 expm1(d t) - d (z_p + z_q)) / (z_p
    // z_q)^2.
    if (pt.near) {
        pt.p1 = pt.eq * (zq_ * pt.em1 - d_) * inv_pq_;
        pt.p2 = pt.eq * (zq_ * zq_ * pt.em1 - d_ * (zp_ + zq_)) * inv_pq_ * inv_pq_;
    } else {
        pt.p1 = pt.ep * inv_p_ - pt.eq * inv_q_;
        pt.p2 = pt.ep * inv_p_ * inv_p_ - pt.eq * inv_q_ * inv_q_;
    }
}

// Slips integrate from one origin t0 through many Newton iterations: remember the last one per
// thread. A slip's next origin is where the last piece ended (a segment end, a stop, a collapse),
// whose exponentials the long-span integral to it has just formed: remember that end as well,
// and take it as the origin when the times agree to the bit (the same point, the same bits).
// The key holds every input, so objects can never see each other's values.
DecaySineIntegrals::Memo& DecaySineIntegrals::memo() const {
    thread_local Memo memo;
    if (memo.p != p_ || memo.q != q_ || memo.omega != omega_) {
        memo = Memo{};
        memo.p = p_;
        memo.q = q_;
        memo.omega = omega_;
    }
    return memo;
}

const DecaySineIntegrals::Point& DecaySineIntegrals::origin(Memo& m, double t0) const {
    if (m.origin.t != t0) {
        if (m.end.t == t0)
            m.origin = m.end;
        else
            pointAt(t0, m.origin);
    }
    return m.origin;
}

// The point just formed is asked for again when an event's state follows its root solve at the
// last point the solve evaluated: the same time, the same bits.
const DecaySineIntegrals::Point& DecaySineIntegrals::endAt(Memo& m, double t) const {
    if (m.end.t != t) pointAt(t, m.end);
    return m.end;
}

// int_0^h (h - u)^(k-1)/(k-1)! exp(z (t0 + u)) du = exp(z t0) h^k phi_k(z h),
// phi_k(w) = sum_n w^n / (n + k)!. The p - q difference is
// exp(z_q t0) h^k [expm1(d t0) phi_k(w_p) + (w_p - w_q) sum_{n>=1} D_n / (n + k)!],
// D_n = (w_p^n - w_q^n) / (w_p - w_q) = w_p D_{n-1} + w_q^{n-1}: no cancellation anywhere.
// One loop forms the sums of k = 1 and, when asked, of k = 2 (both integrals from one series).
DecaySineIntegrals::Series DecaySineIntegrals::series(double h, bool second) const {
    // Plain real arithmetic: std::complex's operator* may go through __muldc3 (NaN rules).
    const double pr = zp_.real() * h, pi = zp_.imag() * h; // w_p
    const double qr = zq_.real() * h, qi = zq_.imag() * h; // w_q
    const double r = zqAbs_ * h;                           // |w_p| <= |w_q| = r <= 1/4
    Series sum; // phi_k starts at 1/k!, the other sums at 0
    sum.phi[0] = {1.0, 0.0};
    sum.phi[1] = {0.5, 0.0};
    double coef = 1.0, coef2 = 0.5, fact = 1.0; // 1/(n + 1)!, 1/(n + 2)!, 1/n!
    double rPow = 1.0;
    double wpR = 1.0, wpI = 0.0, wqR = 1.0, wqI = 0.0, dR = 0.0, dI = 0.0;
    for (int n = 1; n < kSeriesTerms; ++n) {
        coef /= (n + 1);
        // D_n = w_p D_{n-1} + w_q^{n-1} (D_1 = 1, from D_0 = 0 and w_q^0 = 1)
        const double nr = pr * dR - pi * dI + wqR, ni = pr * dI + pi * dR + wqI;
        dR = nr;
        dI = ni;
        const double qR = wqR * qr - wqI * qi, qI = wqR * qi + wqI * qr;
        wqR = qR;
        wqI = qI;
        const double pR = wpR * pr - wpI * pi, pI = wpR * pi + wpI * pr;
        wpR = pR;
        wpI = pI;
        sum.phi[0] += Complex(wpR * coef, wpI * coef);
        sum.div[0] += Complex(dR * coef, dI * coef);
        if (second) {
            coef2 /= (n + 2);
            sum.phi[1] += Complex(wpR * coef2, wpI * coef2);
            sum.div[1] += Complex(dR * coef2, dI * coef2);
        }
        fact /= n;
        sum.expDiv += Complex(dR * fact, dI * fact);
        // |w_p^n| <= r^n and |D_n| <= n r^(n-1): stop once the terms fall below the rounding
        // of the sums (phi ~ 1/k!, the divided sum ~ 1/(k+1)!; k = 1's terms are the larger).
        rPow *= r;
        if (n * rPow * coef < 1e-18 * r) break;
    }
    // exp(w_p) = 1 + w_p phi_1(w_p).
    const Complex phi = sum.phi[0];
    sum.expP = {1.0 + pr * phi.real() - pi * phi.imag(), pr * phi.imag() + pi * phi.real()};
    return sum;
}

// The increment h^k [lead phi + exp(z_q t0) d h div] of one k, lead = exp(z_p t0) - exp(z_q t0).
// Far from the origin (d t0 >= 1) lead is taken as that difference (no cancellation:
// |exp(z_q t0)| <= |exp(z_p t0)| / e), never as exp(z_q t0) expm1(d t0): expm1 overflows once
// d t0 > 709.78 while exp(z_q t0) underflows, and inf x 0 is NaN.
DecaySineIntegrals::Complex DecaySineIntegrals::increment(const Point& o, double dh, double hk,
                                                          Complex phi, Complex div) const {
    if (!o.near)
        return (mul(o.ep - o.eq, phi.real(), phi.imag()) +
                mul(o.eq, dh * div.real(), dh * div.imag())) *
               hk;
    const double e = o.em1;
    return mul(o.eq, e * phi.real() + dh * div.real(), e * phi.imag() + dh * div.imag()) * hk;
}

// The first integral over a short span from o.t; with second, also the second; with end,
// exp(z_p t1) - exp(z_q t1) = exp(z_q t0) [expm1(d t0) exp(w_p) + (w_p - w_q) sum D_n / n!], and
// with endQ exp(z_q t1) = exp(z_q t0) exp(w_q), exp(w_q) = exp(w_p) - (w_p - w_q) sum D_n / n!.
DecaySineIntegrals::Complex DecaySineIntegrals::shortSpan(const Point& o, double h, Complex* second,
                                                          Complex* end, Complex* endQ) const {
    const Series sum = series(h, second != nullptr);
    const double dh = d_ * h;
    const Complex ep = sum.expP, ed = sum.expDiv;
    if (endQ) *endQ = mul(o.eq, ep.real() - dh * ed.real(), ep.imag() - dh * ed.imag());
    if (end)
        *end = o.near ? mul(o.eq, o.em1 * ep.real() + dh * ed.real(),
                            o.em1 * ep.imag() + dh * ed.imag())
                      : mul(o.ep - o.eq, ep.real(), ep.imag()) +
                            mul(o.eq, dh * ed.real(), dh * ed.imag());
    if (second) *second = increment(o, dh, h * h, sum.phi[1], sum.div[1]);
    return increment(o, dh, h, sum.phi[0], sum.div[0]);
}

// g = Im(diff); z_p exp(z_p t) - z_q exp(z_q t) = z_p diff + d eq and
// z_p^2 exp(z_p t) - z_q^2 exp(z_q t) = z_p^2 diff + d (z_p + z_q) eq: no difference of the two
// exponentials is formed.
ShapeAt DecaySineIntegrals::shapeFrom(Complex diff, Complex eq) const {
    const double zr = zp_.real(), zi = zp_.imag();
    const double d1I = zr * diff.imag() + zi * diff.real() + d_ * eq.imag();
    // z_p^2 = (zr^2 - zi^2) + 2 i zr zi; z_p + z_q = -(p + q) + 2 i w.
    const double sR = zr * zr - zi * zi, sI = 2.0 * zr * zi;
    const double tR = -d_ * (p_ + q_), tI = 2.0 * d_ * omega_;
    const double d2I = sR * diff.imag() + sI * diff.real() + tR * eq.imag() + tI * eq.real();
    return {diff.imag(), d1I, d2I};
}

double DecaySineIntegrals::first(double t0, double h, double* valueAtEnd) const {
    Memo& m = memo();
    const Point& o = origin(m, t0);
    if (zqAbs_ * h <= kShortSpan) {
        Complex end;
        const double v = shortSpan(o, h, nullptr, valueAtEnd ? &end : nullptr).imag();
        if (valueAtEnd) *valueAtEnd = end.imag();
        return v;
    }
    const Point& p = endAt(m, t0 + h);
    if (valueAtEnd) *valueAtEnd = (p.near ? p.eq * p.em1 : p.ep - p.eq).imag();
    return (p.p1 - o.p1).imag();
}

double DecaySineIntegrals::firstWithShape(double t0, double h, ShapeAt& end) const {
    Memo& m = memo();
    const Point& o = origin(m, t0);
    if (zqAbs_ * h <= kShortSpan) {
        Complex diff, eq;
        const double v = shortSpan(o, h, nullptr, &diff, &eq).imag();
        end = shapeFrom(diff, eq);
        return v;
    }
    const Point& p = endAt(m, t0 + h);
    end = shapeFrom(p.near ? p.eq * p.em1 : p.ep - p.eq, p.eq);
    return (p.p1 - o.p1).imag();
}

double DecaySineIntegrals::second(double t0, double h) const {
    Memo& m = memo();
    const Point& o = origin(m, t0);
    if (zqAbs_ * h <= kShortSpan) {
        Complex second;
        shortSpan(o, h, &second);
        return second.imag();
    }
    return (endAt(m, t0 + h).p2 - o.p2 - o.p1 * h).imag();
}

// The two integrals over the same span: a short span forms both from one series; a long one
// takes both from the same two points (the memo keeps the origin's and the end's exponentials).
double DecaySineIntegrals::both(double t0, double h, double& secondOut, double* valueAtEnd) const {
    Memo& m = memo();
    const Point& o = origin(m, t0);
    if (zqAbs_ * h <= kShortSpan) {
        Complex second, end;
        const double v = shortSpan(o, h, &second, valueAtEnd ? &end : nullptr).imag();
        secondOut = second.imag();
        if (valueAtEnd) *valueAtEnd = end.imag();
        return v;
    }
    const Point& p = endAt(m, t0 + h);
    if (valueAtEnd) *valueAtEnd = (p.near ? p.eq * p.em1 : p.ep - p.eq).imag();
    secondOut = (p.p2 - o.p2 - o.p1 * h).imag(); // second()'s and first()'s arithmetic
    return (p.p1 - o.p1).imag();
}

} // namespace kinstab
