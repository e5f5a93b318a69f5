// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/rocking/Pulse.h"

#include <cmath>
#include <limits>
#include <numbers>

namespace kinstab {

std::string_view pulseShapeName(PulseShape s) {
    switch (s) {
    case PulseShape::HalfSine:
        return "half-sine";
    case PulseShape::OneSine:
        return "one-sine";
    case PulseShape::OneCosine:
        return "one-cosine";
    case PulseShape::Rectangular:
        return "rectangular";
    }
    return "half-sine";
}

std::optional<PulseShape> pulseShapeFromName(std::string_view name) {
    for (PulseShape s : {PulseShape::HalfSine, PulseShape::OneSine, PulseShape::OneCosine,
                         PulseShape::Rectangular})
        if (pulseShapeName(s) == name) return s;
    return std::nullopt;
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
