// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The state of one run of core/rocking/RockingSolver.h (internal to the solver): the stepping
// (RockingStepping.cpp: DOP853 steps, rest phases, the closed-form end of sliding), the events
// and mode transitions (RockingEvents.cpp, on the table of BlockEvents.h) and the impacts and
// the fate of free rocking (RockingImpact.cpp).

#include "core/rocking/BlockEvents.h"
#include "core/rocking/RockingDynamics.h"
#include "core/rocking/RockingSolver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace kinstab::blockrun {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kHalfPi = 0.5 * std::numbers::pi;
// Free rocking that can no longer overturn is followed this many impacts after the base motion
// has ended when no duration is given (with eta = 1 it would rock for ever).
inline constexpr int kImpactsAfterEnd = 200;
// Rebounds whose heights, all of them summed, stay below this (times alpha) are rest: a block
// bouncing on its base against gravity comes to rest after infinitely many impacts in a finite
// time (Zeno), and its remaining motion is below what a step resolves.
inline constexpr double kRestHeight = 1e-9;
// A rebound slower than this (times p alpha) is rest whatever the base does.
inline constexpr double kRestRebound = 1e-9;

inline double sgn(double x) {
    return x < 0.0 ? -1.0 : 1.0;
}

// One run: the state, the mode, and what happened so far.
class RockingRun {
public:
    RockingRun(const RockingModel& m, const BaseMotion& motion, const RockingRunOptions& o);
    RockingResult go();

private:
    BaseAccel baseAt(double t) const { return {motion_.horizontal(t), motion_.vertical(t)}; }
    BlockState derivative(double t, const BlockState& y) const {
        return blockDerivative(k_, mode_, z_, sigma_, y, baseAt(t));
    }
    // Stepping (RockingStepping.cpp).
    bool restPhase();
    bool integrate();
    bool finishSliding();
    void accept(double t1, const BlockState& y1);
    BlockState stepTo(double t0, const BlockState& y0, const BlockState& f0, double s) const;
    void record(double t, const BlockState& y);
    void recordUpTo(double t0, const BlockState& y0, const BlockState& f0, double t1);
    void countEvent();
    void seeTheta(double theta) {
        r_.maxThetaOverAlpha = std::max(r_.maxThetaOverAlpha, std::abs(theta) / k_.alpha);
    }
    // Events and mode transitions (RockingEvents.cpp). The value of an event function at
    // (t, y, f = y'), and its time derivative when cheap (0 when not: the root search then
    // bisects).
    double eventValue(Event e, double t, const BlockState& y, const BlockState& f,
                      double* slope) const;
    bool watches(Guard g) const;
    bool locateAndApply(double t0, const BlockState& y0, const BlockState& f0, double h,
                        const BlockState& y1, const BlockState& f1);
    void seeApex(double t0, const BlockState& y0, const BlockState& f0, double h,
                 const BlockState& y1, const BlockState& f1, Event first, double sFirst);
    double locate(Event e, double t0, const BlockState& y0, const BlockState& f0, double h,
                  double g0, double s0, double g1, double s1);
    bool apply(Event e);
    bool startMode(BlockMode mode);
    // Impacts and the fate of free rocking (RockingImpact.cpp).
    bool afterImpact();
    bool reboundDies() const;
    void decideFree();

    const BaseMotion& motion_;
    const RockingRunOptions& o_;
    BlockConstants k_;
    double eta_;
    double rockLevel_; // |a_h| / (1 + a_v) that lifts a corner: tan alpha, or alpha
    bool canSlide_;
    double endT_, stopT_;
    bool hasDuration_;
    BlockState absTol_;

    double t_ = 0.0;
    BlockState y_ = BlockState::Zero();
    BlockMode mode_ = BlockMode::Rest;
    double z_ = 1.0, sigma_ = 1.0;
    double h_ = 0.0;
    bool decided_ = false, stop_ = false, overturned_ = false, left_ = false;
    int impactsAfterEnd_ = 0;
    double nextSample_ = 0.0;
    RockingResult r_;
};

} // namespace kinstab::blockrun
