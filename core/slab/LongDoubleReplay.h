// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// An extended-precision reference for one run of the exact solver: its event sequence (which
// events happen, in which order, with which slip sign) is replayed in long double (x87, 64-bit
// significand, about 3 decimal digits beyond double), and each event time is solved again from
// the previous event's long double state with the closed-form integrals of the enveloped sine
// (Furgerson 1980, ch. IV: a(tau) = (A/S_max) (e^{-p tau} - e^{-q tau}) sin(omega tau)).
// It shares the solver's combinatorics (the sequence of events) but none of its arithmetic:
// the work-precision study measures the double solver's error against it.

#include "core/excitation/EnvelopedSine.h"
#include "core/slab/SlabTypes.h"

#include <string>
#include <vector>

namespace kinstab {

struct ReplayResult {
    bool ok = false;     // every event time re-solved near the double one
    std::string failure; // why not, when !ok
    Outcome outcome = Outcome::Failed;
    long double tauC = 0;          // collapse time when collapsed
    long double residualDelta = 0; // final displacement when stable
    long double maxShift = 0;      // largest |long double - double| over the event times
};

// events: the events of solveExact(a, params), as a SlabEventLog recorded them
// (core/slab/SlabRecorder.h).
ReplayResult replayInLongDouble(const EnvelopedSine& a, const SlabParams& params,
                                const std::vector<SlabEvent>& events);

} // namespace kinstab
