// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/slab/LongDoubleReplay.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

namespace kinstab {

namespace {

using Real = long double;
using Complex = std::complex<Real>;
constexpr Real kEps = std::numeric_limits<Real>::epsilon();

// exp(w) - 1 without cancellation: expm1 of the real part, and cos(y) - 1 = -2 sin^2(y/2).
Complex expm1c(Complex w) {
    const Real s = std::sin(0.5L * w.imag());
    return {std::expm1(w.real()) * std::cos(w.imag()) - 2.0L * s * s,
            std::exp(w.real()) * std::sin(w.imag())};
}

// phi_k(w) = sum_n w^n / (n + k)!, k = 1, 2: int_0^h (h - u)^(k-1)/(k-1)! exp(z u) du
// = h^k phi_k(z h). A series for |w| < 1/2 (30 terms: 2^-30 / 31! is far below kEps), else
// from expm1.
Complex phi(int k, Complex w) {
    if (std::abs(w) < 0.5L) {
        Complex sum = 0, term = (k == 1) ? 1.0L : 0.5L;
        for (int n = 0; n < 30; ++n) {
            sum += term;
            term *= w / static_cast<Real>(n + k + 1);
        }
        return sum;
    }
    const Complex e = expm1c(w);
    return k == 1 ? e / w : (e - w) / (w * w);
}

class Replay {
public:
    Replay(const EnvelopedSine& a, const SlabParams& p)
        : p_(a.decayP()), q_(a.decayQ()), omega_(a.omega()), mu_(p.mu), limit_(p.limit),
          zp_(-p_, omega_), zq_(-q_, omega_) {
        scale_ = static_cast<Real>(a.amplitude()) / sMax(a);
    }

    Real accel(Real t) const {
        return scale_ * std::exp(-p_ * t) * -std::expm1(-(q_ - p_) * t) * std::sin(omega_ * t);
    }
    // Changes of the base velocity and displacement over [t0, t0 + h], divided by h and h^2.
    Real dvOverH(Real t0, Real h) const { return scale_ * diff(1, t0, h); }
    Real dxOverH2(Real t0, Real h) const { return scale_ * diff(2, t0, h); }
    Real mu() const { return mu_; }
    Real limit() const { return limit_; }

private:
    Complex expAt(Complex z, Real t) const {
        return std::exp(z.real() * t) * Complex(std::cos(omega_ * t), std::sin(omega_ * t));
    }
    Real diff(int k, Real t0, Real h) const {
        return (expAt(zp_, t0) * phi(k, zp_ * h) - expAt(zq_, t0) * phi(k, zq_ * h)).imag();
    }
    // |e sin| at its maximum: the double solver's half-period peaks locate the hump, a few
    // Newton steps on d/dtau log|e sin| = 0 in long double refine it (S_max is flat there).
    Real sMax(const EnvelopedSine& a) const {
        const double peak = a.envelopePeakTau(); // inf without decay (alpha = 0): from 0 on
        const long k0 =
            std::isfinite(peak) ? static_cast<long>(std::floor(peak / a.halfPeriod())) : 0L;
        Real best = 0;
        for (long k = std::max(0L, k0 - 5); k <= k0 + 5; ++k) {
            Real t = a.halfPeriodPeak(k);
            for (int i = 0; i < 4; ++i) {
                const Real m = std::expm1(-(q_ - p_) * t), d = q_ - p_;
                const Real r1 = -(d + q_ * m) / m, r2 = (d * (p_ + q_) + q_ * q_ * m) / m;
                const Real s = std::sin(omega_ * t), c = std::cos(omega_ * t);
                const Real f = r1 + omega_ * c / s, df = r2 - r1 * r1 - omega_ * omega_ / (s * s);
                t -= f / df;
            }
            best = std::max(best, std::abs(std::exp(-p_ * t) * -std::expm1(-(q_ - p_) * t) *
                                           std::sin(omega_ * t)));
        }
        return best;
    }

    Real p_, q_, omega_, mu_, limit_;
    Complex zp_, zq_;
    Real scale_ = 1;
};

// Secant iteration from the double solver's value x1 (and a point 1e-9 relative beside it).
template <class F> Real secant(F&& f, Real x1) {
    Real x0 = x1 * (1.0L + 1e-9L) + 1e-12L, f0 = f(x0), f1 = f(x1);
    for (int i = 0; i < 60 && f1 != 0.0L && f1 != f0; ++i) {
        const Real x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
        x0 = x1;
        f0 = f1;
        x1 = x2;
        f1 = f(x1);
        if (std::abs(x1 - x0) <= 4.0L * kEps * std::abs(x1)) break;
    }
    return x1;
}

} // namespace

ReplayResult replayInLongDouble(const EnvelopedSine& a, const SlabParams& params,
                                const std::vector<SlabEvent>& events) {
    ReplayResult out;
    const Replay r(a, params);
    Real t0 = 0, x0 = 0, x = 0;
    int s = 0;
    // The slip state from the last onset or reversal (v = 0 there).
    auto xAt = [&](Real h) { return x0 - 0.5L * s * r.mu() * h * h - r.dxOverH2(t0, h) * h * h; };
    auto shifted = [&](Real tau, double guess) {
        const Real shift = std::abs(tau - static_cast<Real>(guess));
        out.maxShift = std::max(out.maxShift, shift);
        return shift <= 1e-6L * (1.0L + std::abs(tau));
    };
    for (const SlabEvent& e : events) {
        Real tau = e.tau;
        switch (e.kind) {
        case EventKind::SlipOnset: {
            // |a| = mu with a against the slip: sign(a) = -s.
            const int sgn = -e.direction;
            tau = secant([&](Real t) { return sgn * r.accel(t) - r.mu(); }, tau);
            t0 = tau;
            x0 = x;
            s = e.direction;
            break;
        }
        case EventKind::Stick:
        case EventKind::Reversal: {
            // v(t0 + h) / h = -s mu - dv / h: the trivial root h = 0 divided out.
            const Real hGuess = static_cast<Real>(e.tau) - t0;
            const Real h =
                hGuess <= 0.0L
                    ? 0.0L
                    : secant([&](Real u) { return -s * r.mu() - r.dvOverH(t0, u); }, hGuess);
            tau = t0 + h;
            x = xAt(h);
            t0 = tau;
            x0 = x;
            s = e.kind == EventKind::Stick ? 0 : e.direction;
            break;
        }
        case EventKind::Collapse: {
            const Real h = secant([&](Real u) { return s * xAt(u) - r.limit(); },
                                  static_cast<Real>(e.tau) - t0);
            tau = t0 + h;
            out.outcome = Outcome::Collapsed;
            out.tauC = tau;
            break;
        }
        case EventKind::Stable:
        case EventKind::DurationCap:
            if (s != 0) x = xAt(tau - t0);
            out.outcome = Outcome::Stable;
            out.residualDelta = x;
            break;
        case EventKind::LiftOff:
            out.failure = "lift-off is not a 1-DOF event";
            return out;
        }
        if (!std::isfinite(tau) || !shifted(tau, e.tau)) {
            out.failure = eventKindName(e.kind) + " at tau " + std::to_string(e.tau) +
                          " moved to " + std::to_string(static_cast<double>(tau));
            return out;
        }
    }
    out.ok = out.outcome != Outcome::Failed;
    if (!out.ok) out.failure = "the run has no final event";
    return out;
}

} // namespace kinstab
