// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a run keeps beyond its summary, chosen by the caller with the recorder it passes, as
// OpenSees recorders and Boost.Odeint observers are: the solver reports each event and each
// accepted state to it and keeps nothing itself, so a run that keeps nothing (a null recorder,
// what a sweep passes) pays one pointer test per event. The planar slab
// (core/slab/PlanarRecorder.h) and the 1-DOF slab (core/slab/SlabRecorder.h) name their own
// events and samples; the shapes below are shared.

#include <vector>

namespace kinstab {

template <class Event, class Sample> class RunRecorder {
public:
    virtual ~RunRecorder() = default;
    virtual void onEvent(const Event& /*event*/) {}
    virtual void onStep(const Sample& /*sample*/) {}
};

// The events, in the order they happened.
template <class Event, class Sample> class RunEventLog : public RunRecorder<Event, Sample> {
public:
    void onEvent(const Event& e) override { events.push_back(e); }
    std::vector<Event> events;
};

// The path: every state the solver reported.
template <class Event, class Sample> class RunPathLog : public RunRecorder<Event, Sample> {
public:
    void onStep(const Sample& s) override { path.push_back(s); }
    std::vector<Sample> path;
};

// Both of two recorders (either may be null), as the caller asks for events, the path or both.
template <class Event, class Sample> class RecorderPair : public RunRecorder<Event, Sample> {
public:
    RecorderPair(RunRecorder<Event, Sample>* first, RunRecorder<Event, Sample>* second)
        : first_(first), second_(second) {}
    void onEvent(const Event& e) override {
        if (first_) first_->onEvent(e);
        if (second_) second_->onEvent(e);
    }
    void onStep(const Sample& s) override {
        if (first_) first_->onStep(s);
        if (second_) second_->onStep(s);
    }

private:
    RunRecorder<Event, Sample>* first_;
    RunRecorder<Event, Sample>* second_;
};

} // namespace kinstab
