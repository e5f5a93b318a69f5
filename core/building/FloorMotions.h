// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The absolute acceleration of every level of a shear building under a ground record, by modal
// superposition of all modes with damping ratio zeta in each:
//   q_r'' + 2 zeta w_r q_r' + w_r^2 q_r = -a_g(t),
//   a_i(t) = sum_r Gamma_r phi_ir (-(2 zeta w_r q_r' + w_r^2 q_r)).
// The bracket is the absolute acceleration of an SDOF oscillator of period T_r, i.e. the
// floor filter's output (core/excitation/FloorFilter.h) for that period: each mode uses its
// exact recurrence for a record linear between samples (Nigam & Jennings 1969).

#include "core/building/ModalModel.h"
#include "core/records/Accelerogram.h"

#include <optional>
#include <vector>

namespace kinstab {

struct FloorMotionOptions {
    double damping = 0.05;      // every mode
    std::optional<double> tail; // s of free vibration after the record; none: as the floor
                                // filter's default for the first mode (decay to 1 %, <= 120 s)
};

// One accelerogram per level, bottom first (level n = roof last), with the tail appended.
// Throws std::invalid_argument on a bad damping or tail, RecordError on a bad record.
std::vector<Accelerogram> floorMotions(const ModalModel& model, const Accelerogram& ground,
                                       const FloorMotionOptions& options = {});

// max |a| of each motion, g.
std::vector<double> peakAccelerations(const std::vector<Accelerogram>& motions);

} // namespace kinstab
