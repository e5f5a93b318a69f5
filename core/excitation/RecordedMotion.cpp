// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/excitation/RecordedMotion.h"

#include "core/base/NextAfter.h"

#include <algorithm>
#include <atomic>
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

namespace {
std::atomic<long> samplesConstructed{0};

// The least double t >= 0 with t / h >= k as the division rounds (so floor(t / h) >= k). The
// rounded quotient is monotone in t, and h k lies within an ulp of the boundary, so a few steps
// of one ulp from h k reach it; 64 bounds the loops far beyond that.
double leastWithFloor(double k, double h) {
    double t = h * k;
    for (int i = 0; i < 64 && !(t / h >= k); ++i)
        t = std::nextafter(t, std::numeric_limits<double>::infinity());
    for (int i = 0; i < 64 && t > 0.0 && std::nextafter(t, 0.0) / h >= k; ++i)
        t = std::nextafter(t, 0.0);
    return t;
}
} // namespace

long RecordSamples::constructed() {
    return samplesConstructed.load();
}

RecordSamples::RecordSamples(const Accelerogram& record, double tstar) {
    if (const std::string e = validateRecordedMotion(record, tstar, std::nullopt); !e.empty())
        throw std::invalid_argument(e);
    h_ = record.dt / tstar;
    a_ = record.samples;
    const std::size_t n = a_.size();
    endTau_ = h_ * static_cast<double>(n - 1);
    inverseH_ = 1.0 / h_;
    suffixMax_.assign(n, 0.0);
    suffixMax_[n - 1] = std::abs(a_[n - 1]);
    for (std::size_t k = n - 1; k-- > 0;)
        suffixMax_[k] = std::max(suffixMax_[k + 1], std::abs(a_[k]));
    knots_.resize(n);
    for (std::size_t k = 0; k < n; ++k)
        knots_[k] = leastWithFloor(static_cast<double>(k), h_);
    ++samplesConstructed;
}

RecordedMotion::RecordedMotion(const Accelerogram& record, double tstar,
                               std::optional<double> targetPeak)
    : RecordedMotion(std::make_shared<const RecordSamples>(record, tstar), targetPeak) {
    // A motion of its own may be shared (a planar case's vertical record is read by every
    // worker thread): form everything now, so that the accessors never write.
    extendTo(samples_->size());
}

RecordedMotion::RecordedMotion(std::shared_ptr<const RecordSamples> samples,
                               std::optional<double> targetPeak)
    : samples_(std::move(samples)), h_(samples_->step()) {
    if (targetPeak) {
        if (!(*targetPeak > 0.0) || !std::isfinite(*targetPeak))
            throw std::invalid_argument("target peak " + std::to_string(*targetPeak) +
                                        " g: must be > 0");
        if (samples_->peak() == 0.0)
            throw std::invalid_argument("the record is all zeros: it cannot be scaled to a peak");
        // The record's own peak is max |a|: the same number as |record.peak().value|.
        scale_ = *targetPeak / samples_->peak();
    }
    // max_k |a_k s| = s max_k |a_k| exactly (rounding is monotone and symmetric), so the bounds
    // and the peak come from the shared suffix maxima times the scale.
    if (std::vector<Piece>* buffer = spare()) pieces_.swap(*buffer);
}

RecordedMotion::~RecordedMotion() {
    std::vector<Piece>* buffer = spare();
    if (buffer && pieces_.capacity() > buffer->capacity()) buffer->swap(pieces_);
}

namespace {
// Set once the thread's spare is destroyed: a trivially destructible flag stays readable after
// the thread's other objects are gone (a view destroyed later must not touch the spare).
thread_local bool spareClosed = false;
} // namespace

std::vector<RecordedMotion::Piece>* RecordedMotion::spare() {
    struct Spare {
        std::vector<Piece> buffer;
        ~Spare() { spareClosed = true; }
    };
    if (spareClosed) return nullptr;
    thread_local Spare s;
    return &s.buffer;
}

// The same expressions, in the same order, as the motion formed all at once: a_k s, then the
// exact integrals of each linear piece.
void RecordedMotion::extendTo(std::size_t count) const {
    const std::size_t n = samples_->size();
    count = std::min(count, n);
    if (count <= built_) return;
    if (pieces_.size() != n) pieces_.resize(n); // a spare buffer holds another run's pieces
    for (std::size_t k = built_; k < count; ++k) {
        Piece& p = pieces_[k];
        p.a = samples_->raw(k) * scale_;
        if (k == 0) {
            p.v = p.d = p.slope = 0.0;
            continue;
        }
        Piece& q = pieces_[k - 1];
        p.v = q.v + h_ * (q.a + p.a) / 2.0;
        p.d = q.d + q.v * h_ + h_ * h_ * (2.0 * q.a + p.a) / 6.0;
        q.slope = (p.a - q.a) / h_;
    }
    if (count == n) pieces_[n - 1].slope = 0.0; // no piece after the last sample
    built_ = count;
}

std::vector<double> RecordedMotion::samples() const {
    std::vector<double> out(samples_->size());
    for (std::size_t k = 0; k < out.size(); ++k)
        out[k] = piece(k).a;
    return out;
}

std::size_t RecordedMotion::interval(double tau) const {
    // floor(tau / h) by a product and a truncation (the division and libm's floor were a tenth
    // of a planar run with a vertical record). The product's rounding differs from the quotient's
    // by a few ulps, so its truncation is k - 1, k or k + 1 for the quotient's floor k; the knots
    // (where the quotient's floor steps) settle which, the same bits as the quotient everywhere.
    if (!(tau > 0.0)) return 0;
    const std::size_t last = samples_->size() - 2;
    const double q = tau * samples_->inverseStep();
    if (!(q < static_cast<double>(last) + 1.0)) return last; // beyond the last knot but one
    const auto k = static_cast<std::size_t>(q);
    if (tau < samples_->knot(k)) return k - 1; // knot(0) = 0 < tau: k > 0 here
    if (tau >= samples_->knot(k + 1)) return std::min(k + 1, last);
    return k;
}

// Inside the record, when lo and the last double before hi fall in one interval, every tau
// between does (interval() is floor(tau / h), monotone).
bool RecordedMotion::linearOn(double lo, double hi, LinearPiece& out) const {
    if (!(lo >= 0.0 && hi > lo && hi <= endTau())) return false;
    const std::size_t k = interval(lo);
    if (interval(nextAfter(hi, lo)) != k) return false;
    const Piece& p = piece(k);
    out = {p.a, h_ * static_cast<double>(k), p.slope};
    return true;
}

double RecordedMotion::accel(double tau) const {
    if (tau < 0.0 || tau > endTau()) return 0.0;
    const std::size_t k = interval(tau);
    const Piece& p = piece(k);
    return p.a + p.slope * (tau - h_ * static_cast<double>(k));
}

double RecordedMotion::accelSlope(double tau) const {
    if (tau < 0.0 || tau > endTau()) return 0.0;
    return slope(interval(tau));
}

double RecordedMotion::firstIntegral(double tau) const {
    if (tau <= 0.0) return 0.0;
    if (tau >= endTau()) return piece(samples_->size() - 1).v;
    const std::size_t k = interval(tau);
    const Piece& p = piece(k);
    const double u = tau - h_ * static_cast<double>(k);
    return p.v + u * (p.a + 0.5 * p.slope * u);
}

double RecordedMotion::secondIntegral(double tau) const {
    if (tau <= 0.0) return 0.0;
    if (tau >= endTau()) {
        const Piece& last = piece(samples_->size() - 1);
        return last.d + last.v * (tau - endTau());
    }
    const std::size_t k = interval(tau);
    const Piece& p = piece(k);
    const double u = tau - h_ * static_cast<double>(k);
    return p.d + u * (p.v + u * (p.a / 2.0 + p.slope * u / 6.0));
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
    // floor(start / h) (interval()'s clamp to the last piece leaves the result at end)
    const auto k = static_cast<double>(interval(start));
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
    const double a0 = piece(k).a, a1 = pieces_[k + 1].a; // piece(k) formed k + 1 too
    const auto at = [&](double tau) {
        const double u = (tau - t0) / h_;
        if (std::abs(u) <= 1e-12) return a0;
        if (std::abs(u - 1.0) <= 1e-12) return a1;
        return a0 + (a1 - a0) * u;
    };
    const double fLo = at(lo) - level;
    const double fHi = at(hi) - level;
    if ((fLo < 0.0 && fHi > 0.0) || (fLo > 0.0 && fHi < 0.0)) {
        const double t = lo + (hi - lo) * fLo / (fLo - fHi);
        c.add(std::clamp(t, nextAfter(lo, hi), nextAfter(hi, lo)));
    }
    return c;
}

double RecordedMotion::boundAfter(double tau) const {
    if (tau > endTau()) return 0.0;
    return samples_->suffixMax(interval(tau)) * scale_;
}

double RecordedMotion::boundOn(double lo, double hi) const {
    if (lo > endTau() || hi < 0.0) return 0.0;
    const std::size_t kLo = interval(lo);
    const std::size_t kHi = std::min(interval(hi) + 1, samples_->size() - 1);
    if (kHi - kLo > 16) return samples_->suffixMax(kLo) * scale_; // a cheap bound for long spans
    double m = 0.0;
    for (std::size_t k = kLo; k <= kHi; ++k)
        m = std::max(m, std::abs(samples_->raw(k) * scale_));
    return m;
}

} // namespace kinstab
