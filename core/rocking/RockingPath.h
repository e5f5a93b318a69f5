// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One run of a block with its path recorded, for an animation or a plot: the solver's samples
// (a fixed interval apart, and at every event, RockingSolver.h) and its result. pathAt reads
// the path at any time by interpolating between the recorded samples, never by integrating
// again, so what is drawn is what the solver computed.

#include "core/rocking/BaseMotion.h"
#include "core/rocking/RockingModel.h"
#include "core/rocking/RockingResult.h"

#include <vector>

namespace kinstab {

struct RockingPath {
    std::vector<RockingSample> samples; // increasing t (equal t at an event: before, after)
    RockingResult result;
};

// Runs the model under the motion recording every sampleInterval seconds (> 0) and at every
// event; an overturning run ends with the state the result gives at its overturning time
// (|theta| = pi/2, the last sample's theta' and u). Throws what simulateRocking throws.
RockingPath recordRocking(const RockingModel& model, const BaseMotion& motion,
                          double sampleInterval);

// The state at time t: linear between the two samples around it (theta, theta', u), the mode of
// the earlier one; before the first sample the first, after the last the last (an overturned
// block lies where it fell). At a time with two samples (an event), the later.
RockingSample pathAt(const std::vector<RockingSample>& samples, double t);

} // namespace kinstab
