// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The overturning map of a pulse shape (Zhang & Makris 2001, figs. 7-9): over the dimensionless
// amplitude a_p / (alpha g) and frequency omega_p / p, whether the block survives or overturns
// (and the largest |theta|/alpha when it survives). Every point a run of simulateRocking on
// core's thread pool, with progress and cancel (core/sweep/SweepControl.h).

#include "core/rocking/Pulse.h"
#include "core/rocking/RockingModel.h"
#include "core/sweep/SweepControl.h"

#include <cstddef>
#include <vector>

namespace kinstab {

struct OverturningMapSpec {
    PulseShape shape = PulseShape::OneSine;
    double amplitudeMin = 0.5, amplitudeMax = 10.0; // a_p / (alpha g), > 0
    double frequencyMin = 0.5, frequencyMax = 10.0; // omega_p / p, > 0 (rectangular: 2 pi /
                                                    // (p t_1), its duration as a period)
    int amplitudePoints = 101, frequencyPoints = 101;
    int threads = 0; // <= 0: all hardware threads
};

// Row-major over (frequency index i, amplitude index j): k = i * amplitudePoints + j.
struct OverturningMap {
    OverturningMapSpec spec;
    std::vector<double> amplitudes;  // a_p / (alpha g)
    std::vector<double> frequencies; // omega_p / p
    // 0: survives, 1: overturns, 2: leaves the base (the corner's normal force vanished: the
    // model cannot follow it, RockingOutcome::LeavesBase)
    std::vector<unsigned char> overturns;
    std::vector<float> maxThetaOverAlpha; // up to the end or the decision (>= 1 if it overturns)
    bool complete = false;                // false: cancelled; points not run are 0 (survives, 0)
    std::size_t at(int i, int j) const {
        return static_cast<std::size_t>(i) * amplitudes.size() + static_cast<std::size_t>(j);
    }
};

// The model's block sets alpha and p (its b, h); the pulse sign is negative (tipping towards +x;
// the map is symmetric). Throws std::invalid_argument for a bad spec.
OverturningMap overturningMap(const RockingModel& model, const OverturningMapSpec& spec,
                              const SweepControl* control = nullptr);

} // namespace kinstab
