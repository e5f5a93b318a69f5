// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One picked point of the surface, run again on demand with its events recorded and its
// history sampled (a sweep keeps only tau_c and the outcome, docs/theory.md §6.6).

#include "core/slab/History.h"
#include "core/slab/PointResult.h"
#include "core/slab/Slab1DCase.h"
#include "core/slab/SlabRecorder.h"

#include <string>
#include <vector>

namespace kinstab::ui {

struct EnvelopeSample {
    double tau = 0;
    double bound = 0; // A e(t* tau) / S_max, g: the envelope the acceleration stays inside
};

struct PointRun : RunPoint {
    double mu = 0, limit = 1;
    std::string drive; // what drove the run when not the sine at (A, f): "record X at 0.9 g"
    SlabResult result;
    History history;
    std::vector<EnvelopeSample> envelope;
};

// Samples about 40 points per period, at most ~40000 in all, and at every event.
PointRun runPoint(const Slab1DCase& c, double amplitude, double frequencyHz);

} // namespace kinstab::ui
