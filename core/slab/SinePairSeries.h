// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The two horizontal components of the planar slab's excitation when both are enveloped sines
// under one envelope (docs/theory.md §6.5), evaluated from local Taylor series instead of four
// transcendental functions per call:
//   a(tau) = K Im[ exp(z_p tau) (1 - exp(-d tau)) ],  z_p = -p + i omega,  d = q - p,
// i.e. K e(tau) sin(omega tau) with e = exp(-p tau) - exp(-q tau). The time line is cut into
// patches of length 1 / |z|max on a fixed grid; about a patch's centre c, with delta = tau - c,
//   a = K Im[ E (-m_c sum_k z_p^k delta^k / k! + (1 + m_c) sum_k (z_p^k - z_q^k) delta^k / k!) ],
// E = exp(z_p c), m_c = expm1(-d c), z_q = z_p - d. The second sum is formed by the recurrence
// z_p^k - z_q^k = z_p (z_p^{k-1} - z_q^{k-1}) + d z_q^{k-1}, so nothing cancels when q ~ p.
// |z delta| <= 1/2 on a patch: the terms past degree 15 are below 1e-18 of K, and the value is a
// pure function of tau (the patch grid does not depend on which times were asked before).
// Not safe to share between threads: it keeps the last patches it built.

#include <array>
#include <complex>
#include <cstddef>

namespace kinstab {

class EnvelopedSine;

class SinePairSeries {
public:
    SinePairSeries(const EnvelopedSine& x, const EnvelopedSine& y);

    // (a_x, a_y) and their slopes at tau; the closed forms outside [0, kMaxTau]. Inline: they
    // are the planar solver's innermost calls (the calls through three files were 4 % of its
    // instructions on the bench grid).
    std::array<double, 2> accel(double tau) {
        double delta = 0.0;
        const Patch* patch = patchFor(tau, delta);
        return patch ? estrin16(patch->c, delta) : closedForm(tau, false);
    }
    std::array<double, 2> slope(double tau) {
        double delta = 0.0;
        const Patch* patch = patchFor(tau, delta);
        return patch ? estrin16(patch->dc, delta) : closedForm(tau, true);
    }
    // Both at once, the same bits as the two calls: one patch lookup and one set of powers of the
    // offset (the onset scans and the slaved slip ask for both at every evaluation).
    void accelAndSlope(double tau, std::array<double, 2>& a, std::array<double, 2>& s) {
        double delta = 0.0;
        if (const Patch* patch = patchFor(tau, delta)) {
            a = estrin16(patch->c, delta);
            s = estrin16(patch->dc, delta);
            return;
        }
        a = closedForm(tau, false);
        s = closedForm(tau, true);
    }

    static constexpr std::size_t kDegree = 15; // the sum is evaluated by a 16-term Estrin scheme
    static constexpr double kMaxTau = 1e7;

private:
    using Pair = std::array<double, 2>; // (x, y)
    struct Component {
        const EnvelopedSine* sine = nullptr;
        std::array<std::complex<double>, kDegree + 1> zp{}; // z_p^k / k!
        std::array<std::complex<double>, kDegree + 1> dz{}; // (z_p^k - z_q^k) / k!
    };
    // A patch's Taylor terms of both components. kPatches are kept, by index modulo kPatches: a
    // step or a root search that straddles a patch boundary would otherwise rebuild them in turn,
    // and a window's onset scan runs ahead over several patches that its slip then steps
    // through again (with two kept, the scans' rebuilds were two thirds of all).
    struct Patch {
        long index = -1;
        std::array<Pair, kDegree + 1> c{};
        std::array<Pair, kDegree + 1> dc{}; // the slope's terms (the last one 0)
    };
    static Component component(const EnvelopedSine& sine, double p, double q);
    // The patch holding tau and tau's offset from its centre; null outside the grid.
    const Patch* patchFor(double tau, double& delta) {
        if (!(tau >= 0.0 && tau <= kMaxTau)) return nullptr;
        const long k = static_cast<long>(tau * inverseLength_);
        Patch& patch = patches_[static_cast<std::size_t>(k) % kPatches];
        if (patch.index != k) build(patch, k);
        delta = tau - (static_cast<double>(k) + 0.5) * length_;
        return &patch;
    }
    void build(Patch& patch, long k) const;
    std::array<double, 2> closedForm(double tau, bool slope) const;
    // sum c[i] x^i for 16 terms by Estrin's scheme, both lanes at once: a tree of depth 4
    // instead of Horner's chain of 15 dependent steps (the sum was a fifth of the planar
    // solver's time).
    static Pair estrin16(const std::array<Pair, kDegree + 1>& c, double x) {
        static_assert(kDegree + 1 == 16);
        auto axpy = [](const Pair& a, const Pair& b, double t) -> Pair {
            return {a[0] + b[0] * t, a[1] + b[1] * t};
        };
        const double x2 = x * x, x4 = x2 * x2, x8 = x4 * x4;
        std::array<Pair, 8> p;
        for (std::size_t i = 0; i < 8; ++i)
            p[i] = axpy(c[2 * i], c[2 * i + 1], x);
        const Pair q0 = axpy(p[0], p[1], x2), q1 = axpy(p[2], p[3], x2), q2 = axpy(p[4], p[5], x2),
                   q3 = axpy(p[6], p[7], x2);
        return axpy(axpy(q0, q1, x4), axpy(q2, q3, x4), x8);
    }

    std::array<Component, 2> lanes_; // x, y
    double p_ = 0.0, q_ = 0.0, length_ = 0.0, inverseLength_ = 0.0;
    static constexpr std::size_t kPatches = 8;
    std::array<Patch, kPatches> patches_;
};

} // namespace kinstab
