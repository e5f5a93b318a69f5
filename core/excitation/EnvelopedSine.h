// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The paper's floor acceleration (Furgerson 1980, ch. IV; docs/theory.md §3), in g, of
// dimensionless time:
//   a(tau) = (A / S_max) e(t* tau) sin(omega tau),  e(t) = exp(-alpha t) - exp(-beta t),
//   omega = 2 pi f t*.
// Its first and second integrals are elementary, so slip phases are integrated exactly.

#include "core/base/InputLimits.h"
#include "core/excitation/DecaySineIntegrals.h"
#include "core/excitation/Envelope.h"
#include "core/excitation/Excitation1D.h"
#include "core/excitation/FrequencyRange.h"

#include <optional>

namespace kinstab {

class EnvelopedSine final : public Excitation1D {
public:
    EnvelopedSine(const Envelope& envelope, double amplitude, double frequencyHz, double tstar);

    double accel(double tau) const override;
    double accelSlope(double tau) const override;
    double velocityChange(double t0, double t1) const override;
    double velocityChangeAndAccel(double t0, double t1, double& accelAtT1) const override;
    double velocityChangeAndSlopes(double t0, double t1, AccelAt& at) const override;
    double displacementChange(double t0, double t1) const override;
    double velocityAndDisplacementChange(double t0, double t1, double& dx) const override;
    double changesAndAccel(double t0, double t1, double& dx, double& accelAtT1) const override;
    double segmentEnd(double segmentStart) const override;
    Crossings crossings(double level, double segmentStart, double segmentEnd) const override;
    double boundAfter(double tau) const override;
    double boundOn(double lo, double hi) const override;
    int humpSign(double lo, double hi) const override;
    double humpCrossing(double level, double lo, double hi, bool rising) const override;
    double peak() const override { return amplitude_; }
    // The closed-form evaluations of a, a' or e'/e made by crossings() and humpCrossing() on
    // this thread (every Newton iteration of their root solves and of the peak search).
    long threadEvaluations() const override { return evaluationCount(); }

    double omega() const { return omega_; }
    double decayP() const { return p_; } // alpha t*
    double decayQ() const { return q_; } // beta t*
    double halfPeriod() const { return halfPeriod_; }
    double sMax() const { return sMax_; }
    double amplitude() const { return amplitude_; }
    double scale() const { return scale_; } // A / S_max: a = scale e sin(omega tau)
    double envelopeAt(double tau) const;    // e(t* tau), unscaled
    // Time of the envelope's maximum (inf when it never decays: alpha = 0).
    double envelopePeakTau() const { return tauEnvelopePeak_; }
    // Where |a| peaks in the half-period [k pi/omega, (k+1) pi/omega].
    double halfPeriodPeak(long k) const;
    // A cheap first guess of halfPeriodPeak(k), within ~1e-3 of it.
    // With logSlope, also e'/e at the half-period's middle, the factor the guess is made of.
    double peakGuess(long k, double* logSlope = nullptr) const;

private:
    static long& evaluationCount(); // per thread, as the memos below
    void envelopeAndSlope(double tau, double& e, double& de) const;
    double boundEnvelopeAt(double tau) const; // envelopeAt, remembered for the bounds
    void logSlopes(double tau, double& r1, double& r2) const; // e'/e and e''/e
    void accelAndSlope(double tau, double& a, double& da) const;
    // a and its first three derivatives at tau: a crossing's Halley steps.
    void accelDerivatives(double tau, double out[4]) const;
    double computeSMax() const;
    long halfPeriodIndex(double segmentStart) const; // as segmentEnd() cuts the time line
    // Half-period k's hump where |a| > target: a point m inside it (|a(m)| > target) and
    // |a(m)|; none when |a| stays at or below target (touching is not crossing).
    struct Hump {
        long k = 0;
        double sign = 1, m = 0, peakValue = 0, envelope = 0;
        double logSlope = 0; // e'/e at the half-period's middle: e(t) ~ e(m) exp(logSlope (t - m))
    };
    struct HumpMemo;
    HumpMemo& humpMemo(long k, double target) const; // the last hump and its solved crossings
    double humpRootOnce(HumpMemo& memo, double target, bool rising) const;
    std::optional<Hump> findHumpAbove(long k, double target) const;
    // Where |a| rises (rising) or falls through target on that hump.
    double humpRoot(const Hump& h, double target, bool rising) const;

    double amplitude_;
    double p_, q_; // alpha t*, beta t*
    double omega_;
    double halfPeriod_;
    double tauEnvelopePeak_;
    double sMax_ = 1.0;
    double scale_ = 1.0; // A / S_max
    DecaySineIntegrals integrals_;
};

// The inputs of an enveloped sine, declared once (core/base/NumberInput.h). t* = √(d / 2g), s,
// the time unit τ = t / t*: 1 ms is a wall 0.02 mm wide, 100 s a wall 200 km wide (the paper's
// 8-inch wall gives 0.099 s); below 1 ms t*² nears the double range's floor in the solvers'
// event searches. The frequency's range has its reasons in core/excitation/FrequencyRange.h.
inline constexpr NumberInput kAmplitudeInput{
    "amplitude", "g", {0.0, limits::kMaxAmplitudeG}, 1.0, "amplitude"};
inline constexpr NumberInput kFrequencyInput{
    "frequency", "Hz", {kMinFrequencyHz, kMaxFrequencyHz}, 1.0, "frequency"};
inline constexpr NumberInput kTstarInput{"tstar", "s", {1e-3, 100.0}, 0.099, "t* = sqrt(d / 2g)"};

// The first input out of its range, or nothing; validateEnvelopedSine says it in words.
InputProblem checkEnvelopedSine(double amplitude, double frequencyHz, double tstar);
std::string validateEnvelopedSine(double amplitude, double frequencyHz, double tstar);

} // namespace kinstab
