// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The base motions a block can stand on, built from kinstab's other excitations: the paper's
// enveloped sine, a record (with its vertical component), the floor motion of a level of the
// building, and the families of amplitudes the critical searches scale.

#include "core/building/FloorSettings.h"
#include "core/codes/Building.h"
#include "core/excitation/Envelope.h"
#include "core/records/Accelerogram.h"
#include "core/rocking/OverturningAmplitude.h"
#include "core/rocking/Pulse.h"

#include <memory>
#include <optional>

namespace kinstab {

// The enveloped sine a(t) = (A / S_max) e(t) sin(2 pi f t) in physical time (docs/theory.md §3),
// cut where the envelope has decayed below 1e-4 of the peak (or at endS when given).
std::unique_ptr<BaseMotion> envelopedSineMotion(const Envelope& e, double amplitudeG,
                                                double frequencyHz,
                                                std::optional<double> endS = std::nullopt);

// A record, linear between samples and zero after its end, scaled so that its horizontal peak is
// targetPeak (g; none: as recorded); the vertical component (g, up), if any, by the same factor.
// Throws std::invalid_argument for a record the excitation refuses.
std::unique_ptr<BaseMotion> recordMotion(const Accelerogram& horizontal,
                                         std::optional<double> targetPeak = std::nullopt,
                                         const Accelerogram* vertical = nullptr);

// The families the critical searches scale: the pulse with amplitude A (the pulse's sign kept),
// the record scaled to peak A (g).
MotionFamily pulseFamily(const Pulse& pulse);
MotionFamily recordFamily(const Accelerogram& horizontal,
                          std::optional<Accelerogram> vertical = std::nullopt);

// The absolute acceleration of level `level` (1 = first above the ground, stories = roof; 0 = the
// ground itself) of the shear building under the ground record (core/building/FloorMotions.h),
// with modal damping `damping`. Throws std::invalid_argument / InputError on bad input.
Accelerogram levelMotion(const Building& b, StiffnessProfile profile, double damping, int level,
                         const Accelerogram& ground);

} // namespace kinstab
