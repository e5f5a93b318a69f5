// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The event-driven solver of a free-standing rigid block on a moving base (docs/theory.md,
// "Free-standing blocks"; Housner 1963; Shenton 1996; Zhang & Makris 2001).
//
// Sign convention. x is horizontal, the base acceleration a_h (g) positive towards +x. theta is
// the block's rotation, > 0 when it rocks about its corner at +x (its top moving towards +x),
// < 0 about the corner at -x. With z = sgn theta, while rocking
//   exact:       theta'' = -p^2 (1 + a_v) [sin(alpha z - theta) + a_h/(1 + a_v) cos(alpha z -
//   theta)] linearised:  theta'' = -p^2 (1 + a_v) [alpha z - theta + a_h/(1 + a_v)]
// (Zhang & Makris 2001 eq. 12 with their a_g = -a_h; a base pushed towards -x tips the block
// towards +x). u is the displacement of the block's base (or pivot corner) relative to the base,
// m, positive towards +x.
//
// Modes and their changes, each located as an event on the integrator's step (DOP853, re-stepped
// to the event time by safeguarded Newton on the event function, so an event is as exact as a
// step):
//   rest -> rock        when -z a_h > tan(alpha) (1 + a_v) (linearised: alpha), if the friction
//                       needed (|a_h| <= mu (1 + a_v)) holds the corner (mu > tan alpha);
//   rest -> slide       when |a_h| > mu (1 + a_v) first (mu < tan alpha; Shenton 1996);
//   slide -> rest       when u' = 0 and |a_h| <= mu (1 + a_v);
//   rock -> slide-rock  when the friction the corner needs exceeds mu N (Zhang & Makris eq. 20);
//   slide-rock -> rock  when the corner's sliding velocity reaches 0 and friction holds it;
//   rock/slide-rock -> leaves base when N reaches 0 (the run stops: LeavesBase);
//   impact at theta = 0: theta' -> eta theta', the block rocks on about the other corner; when
//                       the rebounds that follow would all together lift it less than
//                       1e-9 alpha (the Zeno end of rocking: infinitely many impacts in a
//                       finite time), or |theta'| < 1e-9 p alpha, it is at rest (and lifts
//                       again at once if the base demands it);
//   overturning:        |theta| reaches pi/2 while the base moves; after the base motion has
//                       ended, the fate of free rocking is decided by its energy (a block past
//                       its corner's vertical, |theta| >= alpha, moving outwards never returns;
//                       one below it returns and, after each impact, loses energy), and an
//                       overturning block is followed about its corner to |theta| = pi/2
//                       for its time (its corner may lift on the way: it falls all the same).
// Slide-rock is integrated with the exact equations (both equation choices); the linearised
// choice concerns pure rocking, where the literature's closed forms hold.

#include "core/rocking/BaseMotion.h"
#include "core/rocking/RockingModel.h"
#include "core/rocking/RockingResult.h"

namespace kinstab {

struct RockingRunOptions {
    double relTol = 1e-10; // DOP853's tolerances on theta (abs: relTol alpha) and theta'
    RockingLimits limits;
    RockingRecorder recorder;     // none: no history
    double sampleInterval = 0.01; // s between recorded samples (events are always recorded)
    // Stop as soon as the fate is decided: overturning (no overturning time then), or, without a
    // duration, free rocking that cannot overturn (the map and the critical searches need no
    // more).
    bool stopAtOverturnDecision = false;
    // With stopAtOverturnDecision: a block whose overturning free rocking decides is still
    // followed to |theta| = pi/2 (its impacts on the way counted: the overturning searches tell
    // the branches of overturning apart by them).
    bool followOverturn = false;
};

// One run. Throws std::invalid_argument for a model checkRockingModel refuses, and
// RockingLimitError when a bound of options.limits is reached.
RockingResult simulateRocking(const RockingModel& model, const BaseMotion& motion,
                              const RockingRunOptions& options = {});

} // namespace kinstab
