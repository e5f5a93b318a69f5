// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/excitation/RecordedMotion.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace kinstab {

std::string validateRecordedMotion(const Accelerogram& record, double tstar,
                                   std::optional<double> targetPeak) {
    if (!(tstar > 0.0) || !std::isfinite(tstar))
        return "tstar " + std::to_string(tstar) + ": must be > 0";
    try {
        validateAccelerogram(record);
    } catch (const RecordError& e) {
        return e.message();
    }
    if (targetPeak) {
        if (!(*targetPeak > 0.0) || !std::isfinite(*targetPeak))
            return "target peak " + std::to_string(*targetPeak) + " g: must be > 0";
        if (record.peak().value == 0.0)
            return "the record is all zeros: it cannot be scaled to a peak";
    }
    return {};
}

RecordedMotion::RecordedMotion(const Accelerogram& record, double tstar,
                               std::optional<double> targetPeak) {
    if (const std::string e = validateRecordedMotion(record, tstar, targetPeak); !e.empty())
        throw std::invalid_argument(e);
    h_ = record.dt / tstar;
    scale_ = targetPeak ? *targetPeak / std::abs(record.peak().value) : 1.0;
    a_ = record.samples;
    for (double& x : a_)
        x *= scale_;
    const std::size_t n = a_.size();
    v_.assign(n, 0.0);
    d_.assign(n, 0.0);
    for (std::size_t k = 0; k + 1 < n; ++k) { // exact integrals of the linear piece
        v_[k + 1] = v_[k] + h_ * (a_[k] + a_[k + 1]) / 2.0;
        d_[k + 1] = d_[k] + v_[k] * h_ + h_ * h_ * (2.0 * a_[k] + a_[k + 1]) / 6.0;
    }
    slopes_.assign(n, 0.0);
    for (std::size_t k = 0; k + 1 < n; ++k)
        slopes_[k] = (a_[k + 1] - a_[k]) / h_;
    endTau_ = h_ * static_cast<double>(n - 1);
    inverseH_ = 1.0 / h_;
    suffixMax_.assign(n, 0.0);
    suffixMax_[n - 1] = std::abs(a_[n - 1]);
    for (std::size_t k = n - 1; k-- > 0;)
        suffixMax_[k] = std::max(suffixMax_[k + 1], std::abs(a_[k]));
}

std::size_t RecordedMotion::interval(double tau) const {
    // floor(tau / h) by a product and a truncation (the division and libm's floor were a tenth
    // of a planar run with a vertical record); near a knot, where the product's rounding could
    // land on the other side, by the quotient itself.
    if (!(tau > 0.0)) return 0;
    const std::size_t last = a_.size() - 2;
    const double q = tau * inverseH_;
    if (!(q < static_cast<double>(last) + 1.0)) return last; // beyond the last knot but one
    auto k = static_cast<std::size_t>(q);
    const double frac = q - static_cast<double>(k), guard = 1e-9 * (1.0 + q);
    if (frac < guard || frac > 1.0 - guard) {
        const double exact = std::floor(tau / h_);
        k = exact > 0.0 ? static_cast<std::size_t>(exact) : 0;
    }
    return std::min(k, last);
}

double RecordedMotion::accel(double tau) const {
    if (tau < 0.0 || tau > endTau()) return 0.0;
    const std::size_t k = interval(tau);
    return a_[k] + slope(k) * (tau - h_ * static_cast<double>(k));
}

double RecordedMotion::accelSlope(double tau) const {
    if (tau < 0.0 || tau > endTau()) return 0.0;
    return slope(interval(tau));
}

double RecordedMotion::firstIntegral(double tau) const {
    if (tau <= 0.0) return 0.0;
    if (tau >= endTau()) return v_.back();
    const std::size_t k = interval(tau);
    const double u = tau - h_ * static_cast<double>(k);
    return v_[k] + u * (a_[k] + 0.5 * slope(k) * u);
}

double RecordedMotion::secondIntegral(double tau) const {
    if (tau <= 0.0) return 0.0;
    if (tau >= endTau()) return d_.back() + v_.back() * (tau - endTau());
    const std::size_t k = interval(tau);
    const double u = tau - h_ * static_cast<double>(k);
    return d_[k] + u * (v_[k] + u * (a_[k] / 2.0 + slope(k) * u / 6.0));
}

// Inside one sample interval the local polynomial avoids the cancellation of the prefix sums.
double RecordedMotion::velocityChange(double t0, double t1) const {
    if (t0 >= 0.0 && t1 <= endTau() && interval(t0) == interval(t1)) {
        const double w = t1 - t0;
        return w * (accel(t0) + 0.5 * accelSlope(t0) * w);
    }
    return firstIntegral(t1) - firstIntegral(t0);
}

double RecordedMotion::displacementChange(double t0, double t1) const {
    if (t0 >= 0.0 && t1 <= endTau() && interval(t0) == interval(t1)) {
        const double w = t1 - t0;
        return w * w * (accel(t0) / 2.0 + accelSlope(t0) * w / 6.0);
    }
    return secondIntegral(t1) - secondIntegral(t0) - firstIntegral(t0) * (t1 - t0);
}

double RecordedMotion::segmentEnd(double start) const {
    const double end = endTau();
    if (start >= end) return end + std::max(h_, 2.0 * (start - end)); // a = 0: growing steps
    const double k = std::floor(std::max(start, 0.0) / h_);
    double next = h_ * (k + 1.0);
    if (next <= start) next = h_ * (k + 2.0); // floor rounded down at a sample time
    return std::min(next, end);
}

// a is linear on [lo, hi] (one sample interval): at most one sign change of a - level.
Crossings RecordedMotion::crossings(double level, double lo, double hi) const {
    Crossings c;
    if (!(hi > lo) || lo >= endTau()) return c;
    hi = std::min(hi, endTau());
    const std::size_t k = interval(0.5 * (lo + hi));
    const double t0 = h_ * static_cast<double>(k);
    if (lo < t0 - 1e-12 * h_ || hi > t0 + h_ * (1.0 + 1e-12))
        throw std::logic_error(
            "RecordedMotion::crossings: segment spans more than one sample interval");
    // At a sample time use the sample itself: a level touched at a sample is no crossing inside.
    const auto at = [&](double tau) {
        const double u = (tau - t0) / h_;
        if (std::abs(u) <= 1e-12) return a_[k];
        if (std::abs(u - 1.0) <= 1e-12) return a_[k + 1];
        return a_[k] + (a_[k + 1] - a_[k]) * u;
    };
    const double fLo = at(lo) - level;
    const double fHi = at(hi) - level;
    if ((fLo < 0.0 && fHi > 0.0) || (fLo > 0.0 && fHi < 0.0)) {
        const double t = lo + (hi - lo) * fLo / (fLo - fHi);
        c.add(std::clamp(t, std::nextafter(lo, hi), std::nextafter(hi, lo)));
    }
    return c;
}

double RecordedMotion::boundAfter(double tau) const {
    if (tau > endTau()) return 0.0;
    return suffixMax_[interval(tau)];
}

double RecordedMotion::boundOn(double lo, double hi) const {
    if (lo > endTau() || hi < 0.0) return 0.0;
    const std::size_t kLo = interval(lo);
    const std::size_t kHi = std::min(interval(hi) + 1, a_.size() - 1);
    if (kHi - kLo > 16) return suffixMax_[kLo]; // a cheap bound is enough for long spans
    double m = 0.0;
    for (std::size_t k = kLo; k <= kHi; ++k)
        m = std::max(m, std::abs(a_[k]));
    return m;
}

} // namespace kinstab
