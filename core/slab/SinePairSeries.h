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
// Not safe to share between threads: it keeps the last patch.

#include <array>
#include <complex>

namespace kinstab {

class EnvelopedSine;

class SinePairSeries {
public:
    SinePairSeries(const EnvelopedSine& x, const EnvelopedSine& y);

    // (a_x, a_y) and their slopes at tau; the closed forms outside [0, kMaxTau].
    std::array<double, 2> accel(double tau);
    std::array<double, 2> slope(double tau);

    static constexpr int kDegree = 15; // the sum is evaluated by a 16-term Estrin scheme
    static constexpr double kMaxTau = 1e7;

private:
    struct Component {
        const EnvelopedSine* sine = nullptr;
        double gain = 0.0; // K = A / S_max
        std::array<std::complex<double>, kDegree + 1> zp{},
            dz{};                            // z_p^k / k!, (z_p^k - z_q^k) / k!
        std::array<double, kDegree + 1> c{}; // the current patch's Taylor terms
    };
    static void initComponent(Component& c, double p, double q);
    bool patchFor(double tau, double& delta); // false: outside the grid
    void build(long k);
    static void fill(Component& c, double centre, double ep, double mc);

    Component x_, y_;
    double p_ = 0.0, q_ = 0.0, length_ = 0.0, inverseLength_ = 0.0;
    long patch_ = -1;
};

} // namespace kinstab
