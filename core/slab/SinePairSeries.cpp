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

std::array<double, 2> SinePairSeries::closedForm(double tau, bool slope) const {
    if (slope) return {lanes_[0].sine->accelSlope(tau), lanes_[1].sine->accelSlope(tau)};
    return {lanes_[0].sine->accel(tau), lanes_[1].sine->accel(tau)};
}

} // namespace kinstab
