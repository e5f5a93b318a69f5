// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/rocking/Pulse.h"

#include "core/base/NameTable.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace kinstab {

// PulseShape's names, in its declaration order (HalfSine, OneSine, OneCosine, Rectangular).
constexpr std::array<const char*, 4> kPulseShapeNames = {"half-sine", "one-sine", "one-cosine",
                                                         "rectangular"};
static_assert(kPulseShapeNames.size() == static_cast<std::size_t>(PulseShape::Rectangular) + 1);

std::string_view pulseShapeName(PulseShape s) {
    return enumName(kPulseShapeNames, s);
}

std::optional<PulseShape> pulseShapeFromName(std::string_view name) {
    return enumFromName<PulseShape>(kPulseShapeNames, name);
}

double Pulse::omega() const {
    return 2.0 * std::numbers::pi * frequencyHz;
}

double Pulse::length() const {
    switch (shape) {
    case PulseShape::HalfSine:
        return 0.5 / frequencyHz;
    case PulseShape::OneSine:
    case PulseShape::OneCosine:
        return 1.0 / frequencyHz;
    case PulseShape::Rectangular:
        return durationS;
    }
    return 0.0;
}

InputProblem checkPulse(const Pulse& p) {
    if (auto e = checkInput(kPulseAmplitudeInput, p.amplitude); !e.empty()) return e;
    if (p.shape == PulseShape::Rectangular) return checkInput(kPulseDurationInput, p.durationS);
    return checkInput(kPulseFrequencyInput, p.frequencyHz);
}

PulseMotion::PulseMotion(const Pulse& pulse)
    : pulse_(pulse), omega_(pulse.omega()), end_(pulse.length()),
      quarter_(pulse.shape == PulseShape::Rectangular ? pulse.durationS
                                                      : 0.25 / pulse.frequencyHz) {}

double PulseMotion::horizontal(double t) const {
    if (t < 0.0 || t > end_) return 0.0;
    switch (pulse_.shape) {
    case PulseShape::HalfSine:
    case PulseShape::OneSine:
        return pulse_.amplitude * std::sin(omega_ * t);
    case PulseShape::OneCosine:
        return pulse_.amplitude * std::cos(omega_ * t);
    case PulseShape::Rectangular:
        return pulse_.amplitude;
    }
    return 0.0;
}

// Quarter periods of the sine: between them a sine or cosine is monotone. The rectangular
// pulse is one piece, constant.
double PulseMotion::pieceEnd(double t) const {
    if (t >= end_) return std::numeric_limits<double>::infinity();
    const double k = std::floor(std::max(t, 0.0) / quarter_);
    double next = quarter_ * (k + 1.0);
    if (next <= t) next = quarter_ * (k + 2.0);
    // The last quarter ends where the pulse does, whatever rounding says.
    return end_ - next < 1e-12 * end_ ? end_ : next;
}

double PulseMotion::peak() const {
    return std::abs(pulse_.amplitude);
}

} // namespace kinstab
