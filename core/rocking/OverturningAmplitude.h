// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Which amplitudes of a motion family overturn a block: the smallest one, and the intervals of
// overturning amplitudes up to a maximum, so that a "safe cape" (Zhang & Makris 2001: amplitudes
// above an overturning one that do not overturn) shows. A scan at a fixed step, then bisection of
// every change to a tolerance; bounded. A run in which the block leaves its base (the model
// cannot follow it further: RockingOutcome::LeavesBase) counts as overturning here: nothing
// shows it survives.

#include "core/rocking/BaseMotion.h"
#include "core/rocking/RockingModel.h"
#include "core/sweep/SweepControl.h"

#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace kinstab {

// The base motion of a family at amplitude A (g, > 0): a pulse of that amplitude, a record
// scaled to that peak or by that factor.
using MotionFamily = std::function<std::unique_ptr<BaseMotion>(double amplitude)>;

struct OverturningSearch {
    double maxAmplitude = 5.0; // g (or the family's unit)
    int scanPoints = 200;      // equally spaced amplitudes in (0, maxAmplitude]
    double tolerance = 1e-4;   // relative, of each interval end
    int maxBisections = 60;
};

struct OverturningIntervals {
    // [from, to] of each interval of overturning amplitudes, increasing; the last one's `to` is
    // maxAmplitude when the largest amplitude scanned overturns (open to the maximum).
    std::vector<std::pair<double, double>> intervals;
    std::optional<double> critical() const; // the first `from`, none when nothing overturns
    long runs = 0;
};

// Throws what simulateRocking throws. control: progress (scan points done, of scanPoints) and
// cancel, which stops between runs and returns the intervals found so far (the caller tells a
// cancelled search by control->isCancelled()).
OverturningIntervals overturningIntervals(const RockingModel& model, const MotionFamily& family,
                                          const OverturningSearch& search = {},
                                          const SweepControl* control = nullptr);

} // namespace kinstab
