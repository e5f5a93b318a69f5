// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/excitation/RecordMetrics.h"

#include "core/base/PhysicalConstants.h"
#include "core/excitation/FloorFilter.h"
#include "core/excitation/FourierSpectrum.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace kinstab {

namespace {

// Velocity and displacement of a piecewise-linear acceleration from rest, exactly:
// v1 = v0 + (a0 + a1) dt / 2,  d1 = d0 + v0 dt + (2 a0 + a1) dt^2 / 6.
void integrateMotion(const Accelerogram& a, RecordMetrics& m) {
    const double dt = a.dt;
    double v = 0, d = 0;
    for (std::size_t i = 1; i < a.size(); ++i) {
        const double a0 = a.samples[i - 1] * kStandardGravity;
        const double a1 = a.samples[i] * kStandardGravity;
        d += v * dt + (2.0 * a0 + a1) * dt * dt / 6.0;
        v += 0.5 * (a0 + a1) * dt;
        m.pgv = std::max(m.pgv, std::abs(v));
        m.pgd = std::max(m.pgd, std::abs(d));
    }
    m.finalVelocity = v;
}

// The time where the cumulative integral first reaches `level`, linear between samples.
double crossingTime(const std::vector<double>& cumulative, double dt, double level) {
    const auto it = std::lower_bound(cumulative.begin(), cumulative.end(), level);
    const std::size_t i = static_cast<std::size_t>(it - cumulative.begin());
    if (i == 0) return 0.0;
    if (i >= cumulative.size()) return dt * static_cast<double>(cumulative.size() - 1);
    const double lo = cumulative[i - 1], hi = cumulative[i];
    const double share = hi > lo ? (level - lo) / (hi - lo) : 0.0;
    return dt * (static_cast<double>(i - 1) + share);
}

// Arias intensity and the Husid plot's 5 % and 95 % times. The integral of a^2 over a step of a
// linear a is dt (a0^2 + a0 a1 + a1^2) / 3.
void ariasAndDuration(const Accelerogram& a, RecordMetrics& m) {
    std::vector<double> cumulative(a.size(), 0.0); // integral of a^2 dt, (m/s^2)^2 s
    for (std::size_t i = 1; i < a.size(); ++i) {
        const double a0 = a.samples[i - 1] * kStandardGravity;
        const double a1 = a.samples[i] * kStandardGravity;
        cumulative[i] = cumulative[i - 1] + a.dt * (a0 * a0 + a0 * a1 + a1 * a1) / 3.0;
    }
    const double total = cumulative.back();
    m.arias = std::numbers::pi / (2.0 * kStandardGravity) * total;
    if (!(total > 0.0)) return;
    m.t5 = crossingTime(cumulative, a.dt, 0.05 * total);
    m.t95 = crossingTime(cumulative, a.dt, 0.95 * total);
    m.d5_95 = *m.t95 - *m.t5;
}

// Rathje et al. (1998) use the Fourier amplitudes between 0.25 and 20 Hz with df <= 0.05 Hz;
// the transform is padded to a power of two (core/excitation/FourierSpectrum) and, for short
// records, further until the bins are that fine.
std::optional<double> meanPeriod(const Accelerogram& a) {
    std::vector<double> x = a.samples;
    const std::size_t minPoints = static_cast<std::size_t>(std::ceil(1.0 / (0.05 * a.dt)));
    if (x.size() < minPoints) x.resize(minPoints, 0.0);
    const AmplitudeSpectrum s = amplitudeSpectrum(x, a.dt);
    double weighted = 0, energy = 0;
    for (std::size_t k = 0; k < s.frequency.size(); ++k) {
        const double f = s.frequency[k];
        if (f < 0.25 || f > 20.0) continue;
        const double c2 = s.amplitude[k] * s.amplitude[k];
        weighted += c2 / f;
        energy += c2;
    }
    if (!(energy > 0.0)) return std::nullopt;
    return weighted / energy;
}

} // namespace

double spectralAcceleration(const Accelerogram& a, double period, double damping) {
    const FloorFilterParams p{period, damping, 0.0};
    if (const std::string e = validateFloorFilter(p); !e.empty()) throw std::invalid_argument(e);
    double peak = 0.0;
    for (double x : floorAcceleration(a.samples, a.dt, period, damping))
        peak = std::max(peak, std::abs(x));
    return peak;
}

RecordMetrics recordMetrics(const Accelerogram& a, std::optional<double> saPeriod) {
    validateAccelerogram(a);
    RecordMetrics m;
    m.pga = std::abs(a.peak().value);
    integrateMotion(a, m);
    ariasAndDuration(a, m);
    m.meanPeriod = meanPeriod(a);
    if (saPeriod)
        m.sa = SpectralAcceleration{*saPeriod, kSpectralDamping,
                                    spectralAcceleration(a, *saPeriod, kSpectralDamping)};
    return m;
}

} // namespace kinstab
