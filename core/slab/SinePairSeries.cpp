// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/slab/SinePairSeries.h"

#include "core/excitation/EnvelopedSine.h"

#include <algorithm>
#include <cmath>

namespace kinstab {

SinePairSeries::SinePairSeries(const EnvelopedSine& x, const EnvelopedSine& y)
    : lanes_{component(x, x.decayP(), x.decayQ()), component(y, x.decayP(), x.decayQ())},
      p_(x.decayP()), q_(x.decayQ()) {
    const double zMax = std::max({std::abs(std::complex<double>(-p_, x.omega())),
                                  std::abs(std::complex<double>(-q_, x.omega())),
                                  std::abs(std::complex<double>(-p_, y.omega())),
                                  std::abs(std::complex<double>(-q_, y.omega()))});
    length_ = zMax > 0.0 ? 1.0 / zMax : kMaxTau;
    inverseLength_ = 1.0 / length_;
}

SinePairSeries::Component SinePairSeries::component(const EnvelopedSine& sine, double p, double q) {
    Component c;
    c.sine = &sine;
    const std::complex<double> zp(-p, sine.omega()), zq(-q, sine.omega());
    const double d = q - p;
    std::complex<double> powP(1.0, 0.0), powQ(1.0, 0.0),
        diff(0.0, 0.0); // z_p^k, z_q^k, their difference
    double factorial = 1.0;
    for (std::size_t k = 0; k <= kDegree; ++k) {
        if (k > 0) {
            diff = zp * diff + d * powQ;
            powP *= zp;
            powQ *= zq;
            factorial *= static_cast<double>(k);
        }
        c.zp[k] = powP / factorial;
        c.dz[k] = diff / factorial;
    }
    return c;
}

const SinePairSeries::Patch* SinePairSeries::patchFor(double tau, double& delta) {
    if (!(tau >= 0.0 && tau <= kMaxTau)) return nullptr;
    const long k = static_cast<long>(tau * inverseLength_);
    Patch& patch = patches_[static_cast<std::size_t>(k & 1)];
    if (patch.index != k) build(patch, k);
    delta = tau - (static_cast<double>(k) + 0.5) * length_;
    return &patch;
}

void SinePairSeries::build(Patch& patch, long k) const {
    patch.index = k;
    const double centre = (static_cast<double>(k) + 0.5) * length_;
    const double ep = std::exp(-p_ * centre), mc = std::expm1(-(q_ - p_) * centre);
    for (std::size_t lane = 0; lane < 2; ++lane) {
        const Component& c = lanes_[lane];
        const double phase = c.sine->omega() * centre;
        const std::complex<double> e =
            c.sine->scale() * ep * std::complex<double>(std::cos(phase), std::sin(phase));
        const std::complex<double> ew = -mc * e, ed = (1.0 + mc) * e;
        for (std::size_t i = 0; i <= kDegree; ++i)
            patch.c[i][lane] = (ew * c.zp[i] + ed * c.dz[i]).imag();
    }
    for (std::size_t i = 0; i < kDegree; ++i)
        for (std::size_t lane = 0; lane < 2; ++lane)
            patch.dc[i][lane] = static_cast<double>(i + 1) * patch.c[i + 1][lane];
    patch.dc[kDegree] = {0.0, 0.0};
}

namespace {
using Pair = std::array<double, 2>;
Pair axpy(const Pair& a, const Pair& b, double x) { // a + b x, lane by lane
    return {a[0] + b[0] * x, a[1] + b[1] * x};
}
// sum c[i] x^i for 16 terms by Estrin's scheme, both lanes at once: a tree of depth 4 instead
// of Horner's chain of 15 dependent steps (the sum was a fifth of the planar solver's time).
Pair estrin16(const std::array<Pair, 16>& c, double x) {
    const double x2 = x * x, x4 = x2 * x2, x8 = x4 * x4;
    std::array<Pair, 8> p;
    for (std::size_t i = 0; i < 8; ++i)
        p[i] = axpy(c[2 * i], c[2 * i + 1], x);
    const Pair q0 = axpy(p[0], p[1], x2), q1 = axpy(p[2], p[3], x2), q2 = axpy(p[4], p[5], x2),
               q3 = axpy(p[6], p[7], x2);
    return axpy(axpy(q0, q1, x4), axpy(q2, q3, x4), x8);
}
} // namespace

std::array<double, 2> SinePairSeries::accel(double tau) {
    double delta = 0.0;
    const Patch* patch = patchFor(tau, delta);
    if (!patch) return {lanes_[0].sine->accel(tau), lanes_[1].sine->accel(tau)};
    return estrin16(patch->c, delta);
}

std::array<double, 2> SinePairSeries::slope(double tau) {
    double delta = 0.0;
    const Patch* patch = patchFor(tau, delta);
    if (!patch) return {lanes_[0].sine->accelSlope(tau), lanes_[1].sine->accelSlope(tau)};
    return estrin16(patch->dc, delta);
}

} // namespace kinstab
