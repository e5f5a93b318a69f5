// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What one run of a free-standing block gives: how it ended and the figures of its motion.

#include "core/base/InternalError.h"

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace kinstab {

// The mode the block is in at an instant.
enum class BlockMode {
    Rest,     // on its base, stuck
    Slide,    // on its base, sliding
    Rock,     // on one corner, the corner stuck
    SlideRock // on one corner, the corner sliding
};
std::string_view blockModeName(BlockMode m); // "rest", "slide", "rock", "slide-rock"

// How a run ended, the most severe thing that happened: it overturned; or it left the base (the
// normal force at the corner or base would turn negative: the model cannot follow a flight, the
// run stops there); or it slid and rocked (at once, or one after the other); rocked; slid; or
// stayed at rest.
enum class RockingOutcome { Rest, Slides, Rocks, SlideRock, Overturns, LeavesBase };
std::string_view rockingOutcomeName(RockingOutcome o); // "rest", "slides", "rocks", "slide-rock",
                                                       // "overturns", "leaves-base"

// One sample of the motion for an animation or a plot.
struct RockingSample {
    double t = 0;       // s
    double theta = 0;   // rad, > 0 about the corner at +x
    double omega = 0;   // theta', rad/s
    double sliding = 0; // u, m: the base corner's displacement relative to the base
    BlockMode mode = BlockMode::Rest;
};

// Called with each sample while the run goes on (RockingRunOptions::sampleInterval apart, and at
// every event); the default run records nothing.
using RockingRecorder = std::function<void(const RockingSample&)>;

struct RockingResult {
    RockingOutcome outcome = RockingOutcome::Rest;
    double maxThetaOverAlpha = 0.0;       // max |theta| / alpha over the run (to overturning)
    std::vector<double> impactTimes;      // s, each time theta returned to 0 with theta' != 0
    std::optional<double> overturnTime;   // s, when |theta| reached pi/2 (only if it overturns)
    std::optional<double> leavesBaseTime; // s, when the normal force reached 0 (LeavesBase)
    double slidingDisplacement = 0.0;     // m, u at the end of the run
    double maxSliding = 0.0;              // m, max |u|
    double endTime = 0.0;                 // s, where the run stopped
    bool rocked = false, slid = false, slideRocked = false;
    long steps = 0;  // integrator steps (accepted and rejected)
    long events = 0; // impacts and mode changes
};

// A run that hit one of RockingLimits: what() names the limit and where the run was. A bounded
// search that reached its bound is a result kinstab cannot stand behind (InternalError: the
// command line's exit 4), not the user's fault.
class RockingLimitError : public InternalError {
public:
    using InternalError::InternalError;
};

} // namespace kinstab
