// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Solver of the planar slab (docs/theory.md §5, §6; docs/theory.md §6.1 F4, F7, §6.5): adaptive
// Dormand-Prince 8(5,3) (DOP853; order 8 takes steps several times longer than 5(4) on the smooth
// enveloped sines at the default tolerance) with event location by brackets.
//  - Slip onset |a_h| = mu n is a time-only event: its roots are found ahead on brackets and
//    are step boundaries (tstops). Lift-off n = 0 likewise.
//  - While |u| is small (a slip's start, grazing slips, stops) the direction of u is slaved to
//    -a_h, lagging it by a known small angle: the slip is integrated on that slow manifold in
//    (|u|, dx, dy), which spares the explicit method the stiff alignment of the direction (rate
//    |a|/|u|). The onset roots are scanned only while the slab sticks or is slaved.
//  - The stop |u| -> 0 is approached in the log-radius variable s = ln|u| (docs/theory.md §6.5),
//    where the direction and time are smooth; the stop time is where s -> -inf. A test on the
//    dot product of velocities would fire early (the direction swings by up to 180 degrees in
//    the last instants, F7).
//  - Collapse across (|dx| > limit) or along (|dy| > theta) the walls is located by safeguarded
//    Newton on re-taken steps.
// Each event is a row of one table located the same way (core/slab/PlanarEvents.h); the code is
// split by concern as core/slab/PlanarRun.h lists.

#include "core/slab/PlanarRecorder.h"
#include "core/slab/SlabModel2D.h"

#include <limits>

namespace kinstab {

struct PlanarOptions {
    double relTol = 1e-10;
    double absTol = 1e-12;
    long maxEvents = 2'000'000; // chattering guard
    long maxSteps = 20'000'000;
};

struct PlanarResult {
    // outcome, tauC (collapse or lift-off time), slip intervals, max |dx| and residual dx, work.
    SlabResult slab;
    ExitSide exitSide = ExitSide::None;
    double tauLiftOff = std::numeric_limits<double>::quiet_NaN();
    double maxAbsDeltaY = 0;
    double residualDeltaY = 0;
};

// recorder: what is kept beyond the result (core/slab/PlanarRecorder.h); null: nothing.
PlanarResult solvePlanar(const SlabModel2D& model, const PlanarOptions& options = {},
                         PlanarRecorder* recorder = nullptr);

} // namespace kinstab
