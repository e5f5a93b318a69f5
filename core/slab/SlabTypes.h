// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Inputs and results of one run of a slab model (docs/theory.md §4): value types shared by all
// solvers.

#include "core/base/NumberInput.h"

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace kinstab {

enum class Outcome { Collapsed, Stable, LiftOff, Failed };
std::string outcomeName(Outcome o);

// Which way a planar slab leaves its walls (docs/theory.md §5): across (|dx| > limit) or along
// (|dy| > theta). The 1-DOF slab can only leave across.
enum class ExitSide { None, Across, Along };
std::string exitSideName(ExitSide s); // "across" | "along" | "none"

enum class EventKind {
    SlipOnset, // |a| rose through mu while sticking
    Stick,     // relative velocity reached zero with |a| <= mu
    Reversal,  // relative velocity reached zero with |a| > mu: slides the other way at once
    Collapse,  // |delta| exceeded the bearing limit
    Stable,    // nothing more can happen: the slab sticks and |a| stays below mu
    DurationCap,
    LiftOff,
};
std::string eventKindName(EventKind k);

struct SlabEvent {
    double tau = 0;
    EventKind kind = EventKind::SlipOnset;
    double delta = 0;    // relative displacement, in units of d/2
    double velocity = 0; // relative velocity just after the event
    int direction = 0;   // sign of the slip after the event (0 when sticking)
};

struct SlabParams {
    double mu = 0.6;                // friction coefficient
    double limit = 1.0;             // bearing length / (d/2): collapse when |delta| > limit
    std::optional<double> duration; // tau_out: a finite earthquake
};
// The first input out of its range (μ, limit, duration), or nothing.
InputProblem checkSlabParams(const SlabParams& p);
std::string validateSlabParams(const SlabParams& p); // empty when fine

// What a solver did, so that error can be reported against work (docs/theory.md §6).
struct SolverWork {
    long accelEvaluations = 0; // a(tau) and closed-form integral evaluations
    long rootIterations = 0;
    long steps = 0; // RK4 steps, or segments for the exact solver
    long events = 0;
    long restarts = 0; // paper solver: H -> H/4 restarts
};

struct SlabResult {
    Outcome outcome = Outcome::Failed;
    double tauC = std::numeric_limits<double>::quiet_NaN(); // collapse (or lift-off) time
    double tauEnd = 0;                                      // where the run ended
    std::string failure;                                    // reason when outcome == Failed
    int slipIntervals = 0;
    double maxAbsDelta = 0;
    double residualDelta = 0;
    SolverWork work;
    // The events, a history: what the caller's recorder keeps (core/slab/SlabRecorder.h).
};

struct RunOptions {
    long maxEvents = 2'000'000; // Zeno guard: a run that needs more is reported as failed
    // Exact solver: stop and collapse times are located to this absolute tolerance in tau
    // (0: to a few ulps). Only the work-precision study loosens it.
    double eventTolerance = 0.0;
};

} // namespace kinstab
