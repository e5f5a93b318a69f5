// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a planar run keeps beyond its summary (PlanarResult), chosen by the caller with the
// recorder it passes (core/slab/RunRecorder.h). Ready-made:
//  - none (a null recorder): tau_c, the outcome and the extremes only, as a sweep needs;
//  - PlanarEventLog: the events (onset, stick, reversal, collapse, lift-off, end);
//  - PlanarPathLog: the path, every accepted step and event state;
//  - PlanarRecorderPair: two of them at once.

#include "core/slab/RunRecorder.h"
#include "core/slab/SlabTypes.h"

namespace kinstab {

struct PlanarEvent {
    double tau = 0;
    EventKind kind = EventKind::SlipOnset;
    double dx = 0, dy = 0; // relative displacement
    double ux = 0, uy = 0; // relative velocity just after the event
};

// A point of the computed path: the state after an accepted step or an event.
struct PlanarSample {
    double tau = 0;
    double dx = 0, dy = 0, ux = 0, uy = 0;
    bool slipping = false;
};

using PlanarRecorder = RunRecorder<PlanarEvent, PlanarSample>;
using PlanarEventLog = RunEventLog<PlanarEvent, PlanarSample>;
using PlanarPathLog = RunPathLog<PlanarEvent, PlanarSample>;
using PlanarRecorderPair = RecorderPair<PlanarEvent, PlanarSample>;

} // namespace kinstab
