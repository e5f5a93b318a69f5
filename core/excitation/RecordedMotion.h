// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A recorded acceleration as the base motion of the 1-DOF slab (docs/theory.md §3, §6): the
// samples, optionally scaled to a target peak, linearly interpolated between samples and zero after
// the last one, in the slab's dimensionless time tau = t / t*. On each sample interval a(tau) is
// linear, so the slip velocity and displacement are quadratic and cubic there and the exact
// solver stays exact; the solver's segments are the sample intervals.

#include "core/excitation/Excitation1D.h"
#include "core/records/Accelerogram.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace kinstab {

// What of a recorded motion does not depend on its scale: the unscaled samples, their suffix
// maxima and the step in tau. Built once per record and shared (read-only, so across threads too)
// by every scaled run of a critical search or a study case (issue 34: rebuilding it was about
// half of each run).
class RecordSamples {
public:
    // Throws std::invalid_argument like validateRecordedMotion(record, tstar, {}).
    RecordSamples(const Accelerogram& record, double tstar);

    std::size_t size() const { return a_.size(); }
    double raw(std::size_t k) const { return a_[k]; }               // unscaled, g
    double suffixMax(std::size_t k) const { return suffixMax_[k]; } // max_{j >= k} |a_j|
    double step() const { return h_; }                              // dt / t*
    double inverseStep() const { return inverseH_; }
    double endTau() const { return endTau_; }
    double peak() const { return suffixMax_.front(); } // max |a|, g
    // The least tau with floor(tau / h) >= k (the quotient as the division rounds it), k < size():
    // a time's sample interval follows from the product tau / h estimates and one or two
    // comparisons with these, without the division (issue 34: every window's ends sit on a
    // sample time, where the product's rounding could fall either side, and the division's
    // fallback there was most of the lookup's cost with a vertical record).
    double knot(std::size_t k) const { return knots_[k]; }

    // How many have been built in this process: the tests' observable that a search builds one.
    static long constructed();

private:
    std::vector<double> a_;
    std::vector<double> suffixMax_;
    std::vector<double> knots_;
    double h_ = 1.0;
    double inverseH_ = 1.0;
    double endTau_ = 0.0;
};

class RecordedMotion final : public Excitation1D {
public:
    // targetPeak (g): scales the record so that max |a| equals it; none keeps the record's values.
    RecordedMotion(const Accelerogram& record, double tstar, std::optional<double> targetPeak = {});
    // A run's view of shared samples: only the scale's own prefix integrals are formed, and only
    // as far as the run reaches (a collapse ends it early), with the same arithmetic as the
    // constructor above, so a run gives the same bits either way. The view fills that cache from
    // its const accessors: use one view per run, never one view from two threads.
    RecordedMotion(std::shared_ptr<const RecordSamples> samples,
                   std::optional<double> targetPeak = {});
    RecordedMotion(const RecordedMotion&) = default;
    RecordedMotion& operator=(const RecordedMotion&) = default;
    // Hands its pieces' buffer to the thread's spare, for the next run's view (see spare()).
    ~RecordedMotion() override;

    double accel(double tau) const override;
    double accelSlope(double tau) const override;
    double velocityChange(double t0, double t1) const override;
    double displacementChange(double t0, double t1) const override;
    double segmentEnd(double segmentStart) const override;
    Crossings crossings(double level, double segmentStart, double segmentEnd) const override;
    double boundAfter(double tau) const override;
    double boundOn(double lo, double hi) const override;
    double peak() const override { return samples_->peak() * scale_; }
    bool linearOn(double lo, double hi, LinearPiece& out) const override;

    double sampleStep() const { return h_; }             // dt / t*
    double endTau() const { return samples_->endTau(); } // last sample, h (samples - 1)
    double scale() const { return scale_; }              // applied factor
    std::vector<double> samples() const;                 // scaled, g

private:
    // The scaled sample k with the integrals of a up to it and the slope of the piece after it.
    struct Piece {
        double a = 0, v = 0, d = 0, slope = 0;
    };
    std::size_t interval(double tau) const; // k with tau in [k h, (k+1) h], clamped to the record
    // Piece k with its slope final (piece k + 1 formed too when there is one).
    const Piece& piece(std::size_t k) const {
        if (k + 2 > built_) extendTo(k + 2);
        return pieces_[k];
    }
    void extendTo(std::size_t count) const;
    // One buffer per thread that a view takes at its start and gives back at its end, so that
    // the runs of a critical search or a study allocate no pieces after their first (issue 34);
    // null while the thread's spare is being destroyed at the thread's exit.
    static std::vector<Piece>* spare();
    double slope(std::size_t k) const { return piece(k).slope; } // (a_{k+1} - a_k) / h
    double firstIntegral(double tau) const;                      // int_0^tau a
    double secondIntegral(double tau) const;                     // int_0^tau int_0^s a

    std::shared_ptr<const RecordSamples> samples_;
    double scale_ = 1.0;
    double h_ = 1.0;
    mutable std::vector<Piece> pieces_;
    mutable std::size_t built_ = 0; // pieces [0, built_) hold a, v, d; slopes all but the last
};

// Empty when the record can drive the slab, else a message naming the field and value.
std::string validateRecordedMotion(const Accelerogram& record, double tstar,
                                   std::optional<double> targetPeak);

} // namespace kinstab
