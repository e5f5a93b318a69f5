// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A recorded acceleration as the base motion of the 1-DOF slab (docs/theory.md §3, §6): the
// samples, optionally scaled to a target peak, linearly interpolated between samples and zero after
// the last one, in the slab's dimensionless time tau = t / t*. On each sample interval a(tau) is
// linear, so the slip velocity and displacement are quadratic and cubic there and the exact
// solver stays exact; the solver's segments are the sample intervals.

#include "core/excitation/Excitation1D.h"
#include "core/records/Accelerogram.h"

#include <optional>
#include <string>
#include <vector>

namespace kinstab {

class RecordedMotion final : public Excitation1D {
public:
    // targetPeak (g): scales the record so that max |a| equals it; none keeps the record's values.
    RecordedMotion(const Accelerogram& record, double tstar, std::optional<double> targetPeak = {});

    double accel(double tau) const override;
    double accelSlope(double tau) const override;
    double velocityChange(double t0, double t1) const override;
    double displacementChange(double t0, double t1) const override;
    double segmentEnd(double segmentStart) const override;
    Crossings crossings(double level, double segmentStart, double segmentEnd) const override;
    double boundAfter(double tau) const override;
    double boundOn(double lo, double hi) const override;
    double peak() const override { return suffixMax_.front(); }

    double sampleStep() const { return h_; }                  // dt / t*
    double endTau() const { return endTau_; }                 // last sample, h (samples - 1)
    double scale() const { return scale_; }                   // applied factor
    const std::vector<double>& samples() const { return a_; } // scaled, g

private:
    std::size_t interval(double tau) const; // k with tau in [k h, (k+1) h], clamped to the record
    double slope(std::size_t k) const { return slopes_[k]; } // (a_{k+1} - a_k) / h
    double firstIntegral(double tau) const;                  // int_0^tau a
    double secondIntegral(double tau) const;                 // int_0^tau int_0^s a

    std::vector<double> a_;
    std::vector<double> v_, d_;     // first and second integrals at the samples
    std::vector<double> suffixMax_; // max_{j >= k} |a_j|
    // The pieces' slopes and the end, formed once: they were a tenth of a planar run with a
    // vertical record (a division on every evaluation).
    std::vector<double> slopes_;
    double h_ = 1.0;
    double inverseH_ = 1.0;
    double endTau_ = 0.0;
    double scale_ = 1.0;
};

// Empty when the record can drive the slab, else a message naming the field and value.
std::string validateRecordedMotion(const Accelerogram& record, double tstar,
                                   std::optional<double> targetPeak);

} // namespace kinstab
