// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A sampled history of one run, rebuilt on demand from its event list: between events the
// motion has a closed form, so a sweep never stores histories (docs/theory.md §6.6).

#include "core/excitation/Excitation1D.h"
#include "core/slab/SlabTypes.h"

#include <string>
#include <vector>

namespace kinstab {

struct HistorySample {
    double tau = 0;
    double accel = 0;    // a(tau), g
    double delta = 0;    // relative displacement / (d/2)
    double velocity = 0; // relative velocity
    int state = 0;       // 0 sticking, +1 / -1 slipping in that direction
};

struct History {
    std::vector<HistorySample> samples;
};

// Empty when a history from 0 to tauEnd every `step` stays within limits::kMaxHistoryRows
// (core/base/InputLimits.h), else why not: callers name their step flag or field with it.
std::string validateHistoryStep(double tauEnd, double step);
// Samples every `step` from 0 to tauEnd and at every event time. Throws std::invalid_argument
// with validateHistoryStep's message when the step is too fine.
History sampleHistory(const Excitation1D& a, double mu, const std::vector<SlabEvent>& events,
                      double tauEnd, double step);
// The relative state at one time, from the events before it.
HistorySample stateAt(const Excitation1D& a, double mu, const std::vector<SlabEvent>& events,
                      double tau);

std::string historyCsv(const History& h);

} // namespace kinstab
