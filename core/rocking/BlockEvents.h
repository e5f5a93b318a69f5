// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The events a rocking run watches, as one table per mode: the idea of the planar slab's event
// table (core/slab/PlanarEvents.h, after SUNDIALS CVODE's root functions g_i(t, y)). Each row
// is an event function g that falls through zero (g >= 0 at a step's start, g < 0 at its end)
// when the event happens, and a guard saying when the mode watches it; every row is located the
// same way (core/rocking/RockingRun.h, locate) and the earliest wins, ties to the earlier row.

#include "core/rocking/RockingResult.h"

#include <span>

namespace kinstab::blockrun {

// The events a step can end on. Apex (theta' = 0 outwards) changes nothing but the maximum and
// is sought apart, up to the first event.
enum class Event {
    None,
    Impact,    // g = z theta: the block lands on its base
    Overturn,  // g = pi/2 - z theta
    Normal,    // g = N: the base's normal force vanishes, the block would leave it
    Friction,  // g = mu N - |F|: the rocking corner's friction no longer holds it
    SlideStop, // g = the sliding velocity along its direction
    Apex       // g = z theta'
};

// When a mode watches a row.
enum class Guard {
    Always,
    Vertical,      // the base motion has a vertical component
    NotOverturned, // overturning is not yet decided (then the block is followed to pi/2)
    CanSlide       // the block has friction (mu given)
};

struct WatchedEvent {
    Event event;
    Guard guard;
};

// Once overturning is decided the block is followed about its corner to |theta| = pi/2 for the
// time; a corner lifting on the way does not change that it falls (Normal's guard).
inline constexpr WatchedEvent kSlideEvents[] = {{Event::SlideStop, Guard::Always},
                                                {Event::Normal, Guard::Vertical}};
inline constexpr WatchedEvent kRockEvents[] = {{Event::Impact, Guard::Always},
                                               {Event::Overturn, Guard::Always},
                                               {Event::Normal, Guard::NotOverturned},
                                               {Event::Friction, Guard::CanSlide}};
inline constexpr WatchedEvent kSlideRockEvents[] = {{Event::Impact, Guard::Always},
                                                    {Event::Overturn, Guard::Always},
                                                    {Event::Normal, Guard::NotOverturned},
                                                    {Event::SlideStop, Guard::Always}};

// The table of a moving mode (Rest has none: its events are the base's, core/rocking/
// RockingStepping.cpp).
inline std::span<const WatchedEvent> watchedEvents(BlockMode mode) {
    if (mode == BlockMode::Slide) return kSlideEvents;
    if (mode == BlockMode::SlideRock) return kSlideRockEvents;
    return kRockEvents;
}

} // namespace kinstab::blockrun
