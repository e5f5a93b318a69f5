// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a 1-DOF run keeps beyond its summary (SlabResult), chosen by the caller with the
// recorder it passes to solveExact, solvePaperRk4 or runSlab1D (core/slab/RunRecorder.h), as
// the planar run's (core/slab/PlanarRecorder.h). Ready-made:
//  - none (a null recorder, the default): tau_c, the outcome and the extremes only, as a sweep
//    needs; nothing is kept;
//  - SlabEventLog: the events (onset, stick, reversal, collapse, the end);
//  - SlabHistoryLog: the sampled history, rebuilt from the events in closed form
//    (core/slab/History.h): between events the motion has one, so no step is stored.
// The 1-DOF solvers report events only (onStep is the shared shape's, which the planar solver
// calls): the exact solver takes no steps, its motion between events has a closed form from
// which SlabHistoryLog samples any time; the 1980 RK4 baseline reports the events it located,
// those of the attempt that succeeded.

#include "core/excitation/Excitation1D.h"
#include "core/slab/History.h"
#include "core/slab/RunRecorder.h"
#include "core/slab/SlabTypes.h"

namespace kinstab {

using SlabRecorder = RunRecorder<SlabEvent, HistorySample>;
using SlabEventLog = RunEventLog<SlabEvent, HistorySample>;

// The events, and the history sampled from them on demand. The history's end and step are the
// caller's, chosen once the run is known (a stable run is often shown past its end, and the
// step follows the run's length); a: the run's own excitation, outliving the log.
class SlabHistoryLog : public SlabEventLog {
public:
    SlabHistoryLog(const Excitation1D& a, double mu) : a_(&a), mu_(mu) {}
    // Every `step` from 0 to tauEnd and at every event (sampleHistory); throws
    // std::invalid_argument as sampleHistory does when the step is too fine.
    History history(double tauEnd, double step) const {
        return sampleHistory(*a_, mu_, events, tauEnd, step);
    }

private:
    const Excitation1D* a_;
    double mu_;
};

} // namespace kinstab
