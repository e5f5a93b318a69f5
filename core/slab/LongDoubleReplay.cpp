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

// The slip state since the last onset, reversal or stick (v = 0 there), carried from event to
// event; each event's time is solved again from it in long double.
class EventReplay {
public:
    EventReplay(const Replay& r, ReplayResult& out) : r_(r), out_(out) {}

    // The event's time in long double (lift-off is no 1-DOF event: the caller refuses it).
    Real replay(const SlabEvent& e) {
        switch (e.kind) {
        case EventKind::SlipOnset:
            return onset(e);
        case EventKind::Stick:
        case EventKind::Reversal:
            return stopOrReverse(e);
        case EventKind::Collapse:
            return collapse(e);
        case EventKind::Stable:
        case EventKind::DurationCap:
            return end(e);
        case EventKind::LiftOff:
            break;
        }
        return std::numeric_limits<Real>::quiet_NaN();
    }

private:
    Real xAt(Real h) const {
        return x0_ - 0.5L * s_ * r_.mu() * h * h - r_.dxOverH2(t0_, h) * h * h;
    }
    // |a| = mu with a against the slip: sign(a) = -s.
    Real onset(const SlabEvent& e) {
        const int sgn = -e.direction;
        const Real tau = secant([&](Real t) { return sgn * r_.accel(t) - r_.mu(); }, e.tau);
        t0_ = tau;
        x0_ = x_;
        s_ = e.direction;
        return tau;
    }
    // v(t0 + h) / h = -s mu - dv / h: the trivial root h = 0 divided out.
    Real stopOrReverse(const SlabEvent& e) {
        const Real hGuess = static_cast<Real>(e.tau) - t0_;
        const Real h =
            hGuess <= 0.0L
                ? 0.0L
                : secant([&](Real u) { return -s_ * r_.mu() - r_.dvOverH(t0_, u); }, hGuess);
        const Real tau = t0_ + h;
        x_ = xAt(h);
        t0_ = tau;
        x0_ = x_;
        s_ = e.kind == EventKind::Stick ? 0 : e.direction;
        return tau;
    }
    Real collapse(const SlabEvent& e) {
        const Real h = secant([&](Real u) { return s_ * xAt(u) - r_.limit(); },
                              static_cast<Real>(e.tau) - t0_);
        const Real tau = t0_ + h;
        out_.outcome = Outcome::Collapsed;
        out_.tauC = tau;
        return tau;
    }
    Real end(const SlabEvent& e) {
        const Real tau = e.tau;
        if (s_ != 0) x_ = xAt(tau - t0_);
        out_.outcome = Outcome::Stable;
        out_.residualDelta = x_;
        return tau;
    }

    const Replay& r_;
    ReplayResult& out_;
    Real t0_ = 0, x0_ = 0, x_ = 0;
    int s_ = 0;
};

// Whether the long double time stays near the double one; the largest shift is kept.
bool nearGuess(ReplayResult& out, Real tau, double guess) {
    const Real shift = std::abs(tau - static_cast<Real>(guess));
    out.maxShift = std::max(out.maxShift, shift);
    return shift <= 1e-6L * (1.0L + std::abs(tau));
}

} // namespace

ReplayResult replayInLongDouble(const EnvelopedSine& a, const SlabParams& params,
                                const std::vector<SlabEvent>& events) {
    ReplayResult out;
    const Replay r(a, params);
    EventReplay state(r, out);
    for (const SlabEvent& e : events) {
        if (e.kind == EventKind::LiftOff) {
            out.failure = "lift-off is not a 1-DOF event";
            return out;
        }
        const Real tau = state.replay(e);
        if (!std::isfinite(tau) || !nearGuess(out, tau, e.tau)) {
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
