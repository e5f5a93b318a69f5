// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a planar run keeps beyond its summary (PlanarResult), chosen by the caller with the
// recorder it passes, as OpenSees recorders and Boost.Odeint observers are: the solver reports
// each event and each accepted state to it and keeps nothing itself. Ready-made:
//  - none (a null recorder): tau_c, the outcome and the extremes only, as a sweep needs;
//  - PlanarEventLog: the events (onset, stick, reversal, collapse, lift-off, end);
//  - PlanarPathLog: the path, every accepted step and event state;
//  - PlanarRecorderPair: two of them at once.

#include "core/slab/SlabTypes.h"

#include <vector>

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

class PlanarRecorder {
public:
    virtual ~PlanarRecorder() = default;
    virtual void onEvent(const PlanarEvent& /*event*/) {}
    virtual void onStep(const PlanarSample& /*sample*/) {}
};

class PlanarEventLog : public PlanarRecorder {
public:
    void onEvent(const PlanarEvent& e) override { events.push_back(e); }
    std::vector<PlanarEvent> events;
};

class PlanarPathLog : public PlanarRecorder {
public:
    void onStep(const PlanarSample& s) override { path.push_back(s); }
    std::vector<PlanarSample> path;
};

// Both of two recorders (either may be null), as the caller asks for events, the path or both.
class PlanarRecorderPair : public PlanarRecorder {
public:
    PlanarRecorderPair(PlanarRecorder* first, PlanarRecorder* second)
        : first_(first), second_(second) {}
    void onEvent(const PlanarEvent& e) override {
        if (first_) first_->onEvent(e);
        if (second_) second_->onEvent(e);
    }
    void onStep(const PlanarSample& s) override {
        if (first_) first_->onStep(s);
        if (second_) second_->onStep(s);
    }

private:
    PlanarRecorder* first_;
    PlanarRecorder* second_;
};

} // namespace kinstab
