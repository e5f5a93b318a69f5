// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The pulses of the rocking literature as base motions, starting at t = 0 (Makris & Roussos
// 2000; Zhang & Makris 2001; Housner 1963), amplitude a_p in g, circular frequency
// omega_p = 2 pi f_p:
//   half-sine    a(t) = a_p sin(omega_p t),        0 <= t <= pi / omega_p
//   one-sine     a(t) = a_p sin(omega_p t),        0 <= t <= 2 pi / omega_p
//   one-cosine   a(t) = a_p cos(omega_p t),        0 <= t <= 2 pi / omega_p
//   rectangular  a(t) = a_p,                       0 <= t <= t_1
// and zero afterwards. A positive a pushes the base towards +x, so the block's inertia tips it
// towards -x (theta < 0, RockingSolver.h): negate the amplitude for the other direction.

#include "core/base/InputLimits.h"
#include "core/base/NumberInput.h"
#include "core/excitation/FrequencyRange.h"
#include "core/rocking/BaseMotion.h"

#include <optional>
#include <string>
#include <string_view>

namespace kinstab {

enum class PulseShape { HalfSine, OneSine, OneCosine, Rectangular };

std::string_view pulseShapeName(PulseShape s); // "half-sine", "one-sine", ...
std::optional<PulseShape> pulseShapeFromName(std::string_view name);

struct Pulse {
    PulseShape shape = PulseShape::HalfSine;
    double amplitude = 0.5;   // a_p, g (any sign)
    double frequencyHz = 1.0; // f_p (sine shapes)
    double durationS = 0.5;   // t_1 (rectangular)
    double omega() const;     // 2 pi f_p, rad/s
    double length() const;    // s, when the pulse ends
};

// The pulse inputs, declared once. The amplitude's magnitude as the rest of kinstab limits it.
inline constexpr NumberInput kPulseAmplitudeInput{
    "amplitude", "g", {-limits::kMaxAmplitudeG, limits::kMaxAmplitudeG}, 0.5, "pulse amplitude"};
inline constexpr NumberInput kPulseFrequencyInput{
    "pulse_frequency", "Hz", {kMinFrequencyHz, kMaxFrequencyHz}, 1.0, "pulse frequency"};
inline constexpr NumberInput kPulseDurationInput{
    "pulse_duration", "s", {0.0, 1e4, true}, 0.5, "pulse duration"};

InputProblem checkPulse(const Pulse& p);

class PulseMotion final : public BaseMotion {
public:
    explicit PulseMotion(const Pulse& pulse);
    double horizontal(double t) const override;
    double end() const override { return end_; }
    double pieceEnd(double t) const override; // quarter periods: a_h monotone inside
    double peak() const override;

private:
    Pulse pulse_;
    double omega_;
    double end_;
    double quarter_;
};

} // namespace kinstab
