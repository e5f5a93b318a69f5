// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The 1980 solver, kept as the baseline (Furgerson 1980, Appendix): classical RK4 with a fixed
// step H, a first step of H/2, slip onset by Newton iteration from the step's midpoint, the
// stick time from a quadratic through the last three relative velocities (divided differences),
// collapse tested at step ends, restart from the beginning with H/4 on a failure, and give up
// after three failures.

#include "core/excitation/Excitation1D.h"
#include "core/slab/SlabRecorder.h"
#include "core/slab/SlabTypes.h"

namespace kinstab {

struct PaperSettings {
    double step = 0.0;   // H in dimensionless time (the paper: period / 16)
    int maxFailures = 3; // the paper abandons the case after three failures
    long maxSteps = 50'000'000;
};

// recorder: what is kept beyond the result (core/slab/SlabRecorder.h); null: nothing. It hears
// the events of the attempt that succeeds only, once that attempt has ended.
SlabResult solvePaperRk4(const Excitation1D& excitation, const SlabParams& params,
                         const PaperSettings& settings, const RunOptions& options = {},
                         SlabRecorder* recorder = nullptr);

} // namespace kinstab
