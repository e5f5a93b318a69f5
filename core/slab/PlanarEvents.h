// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The planar slab's events as root functions, as SUNDIALS CVODE's g_i(t, y) (Hindmarsh et al.
// 2005, "SUNDIALS", ACM TOMS 31(3), CVODE's rootfinding): each event is a row of one table,
// (function, direction, kind), and every row is found the same way.
//  - Time events (slip onset |a_h| = mu n, lift-off n = 0) depend on tau alone: their roots are
//    scanned ahead on each window (core/numerics/LevelCrossings.h) and become step boundaries.
//  - State events (collapse across or along the walls, a stop, a piece's end in s = ln|u|) are
//    g = sign (offset + y_k) - level on a component of the stepper's state: detected on the
//    accepted step's end and located by one locator on the step's dense output.

#include "core/numerics/RootFinding.h"
#include "core/slab/SlabModel2D.h"
#include "core/slab/SlabTypes.h"

#include <algorithm>
#include <array>

namespace kinstab::planar {

// Which way g passes zero when the event happens.
enum class Direction {
    Rising, // from g <= 0 to g > 0
    Falling // from g > 0 to g <= 0
};

// A function of tau alone and its slope, evaluated together (a member of the model: the scan
// needs both at every point, and the excitation is evaluated once for them).
struct TimeEvent {
    EventKind kind;
    void (SlabModel2D::*gAndSlope)(double, double&, double&) const;
    Direction direction;
};

// Lift-off first: where n reaches 0 the window ends, and only then are onsets sought in it.
inline constexpr std::array<TimeEvent, 2> kTimeEvents{{
    {EventKind::LiftOff, &SlabModel2D::liftMarginAndSlope, Direction::Rising},
    {EventKind::SlipOnset, &SlabModel2D::onsetMarginAndSlope, Direction::Rising},
}};
inline constexpr const TimeEvent& kLiftOffEvent = kTimeEvents[0];
inline constexpr const TimeEvent& kOnsetEvent = kTimeEvents[1];

// g = sign (offset + y_k) - level: component k of a stepper's state crossing a level (the offset
// turns a state's elapsed time into tau). The form keeps each location bit for bit what the
// solver's earlier per-event code computed.
// What a state event means for the run.
enum class StateKind {
    CollapseAcross, // |dx| passed the bearing limit
    CollapseAlong,  // |dy| passed theta
    Stop,           // |u| reached 0: the slab sticks or reverses (decided there)
    PieceEnd        // tau reached the end of the piece being integrated in another variable
};

struct StateEvent {
    StateKind kind = StateKind::CollapseAcross;
    Direction direction = Direction::Rising;
    int component = 0;
    double sign = 1.0;
    double level = 0.0;
    double offset = 0.0;

    double value(double yk) const { return sign * (offset + yk) - level; }
    double rate(double dyk) const { return sign * dyk; }
    bool fired(double g) const { return direction == Direction::Rising ? g > 0.0 : !(g > 0.0); }
    // The same event on another stepper's state, whose displacement starts at `first`.
    StateEvent shifted(int first) const {
        StateEvent e = *this;
        e.component += first;
        return e;
    }
};

// The walls' edges on the displacement (dx, dy) = state components 0, 1, in the order they are
// checked: across (|dx| > limit) before along (|dy| > theta).
using WallEvents = std::array<StateEvent, 4>;
WallEvents wallEvents(const PlanarParams& p);

// The first row whose function has fired at the state y (component k read as y[k + first]), or
// null.
template <class State>
const StateEvent* firstFired(const WallEvents& table, const State& y, int first = 0) {
    for (const StateEvent& e : table)
        if (e.fired(e.value(y[e.component + first]))) return &e;
    return nullptr;
}

// The one locator: where g crosses zero inside a step, on the step's dense output. at(x, yk,
// dyk) gives the event's component and its rate at x (the stepper re-taken from the step's start
// to x, as accurate as the step itself); glo, ghi = g at lo, hi, of opposite signs. Safeguarded
// Newton, clamped into the bracket; iterations counts its work.
template <class Dense>
double locateEvent(const StateEvent& e, Dense&& at, double lo, double hi, double glo, double ghi,
                   long& iterations) {
    const RootResult root = safeguardedNewton(
        [&](double x, double& g, double& dg) {
            double yk = 0.0, dyk = 0.0;
            at(x, yk, dyk);
            g = e.value(yk);
            dg = e.rate(dyk);
        },
        lo, hi, glo, ghi);
    iterations += root.iterations;
    return std::clamp(root.x, std::min(lo, hi), std::max(lo, hi));
}

} // namespace kinstab::planar
