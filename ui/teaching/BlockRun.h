// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One run of a free-standing block for the Teaching tab: the case (block model and pulse, or
// free rocking from a tilt), core's recorded path (core/rocking/RockingPath.h) and what the
// animation needs from it: the events to step between, the end, the base acceleration at a time.
// The run is core's; the view only samples it.

#include "core/rocking/Pulse.h"
#include "core/rocking/RockingPath.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace kinstab::ui {

struct BlockCase {
    RockingModel model;         // initialTilt > 0 with no pulse: Housner's free rocking
    std::optional<Pulse> pulse; // none: no base motion
};

// The animation's sample spacing: 200 frames per second of motion, finer than the play's 25.
inline constexpr double kBlockSampleInterval = 0.005;

class BlockRun {
public:
    BlockRun() = default;
    explicit BlockRun(const BlockCase& c); // runs core's solver (an error is kept, not thrown)

    const BlockCase& blockCase() const { return case_; }
    const RockingPath& path() const { return path_; }
    const RockingResult& result() const { return path_.result; }
    const std::string& error() const { return error_; }
    double alpha() const;
    double p() const;
    // s: the last recorded sample, and a little past the pulse when it ends later.
    double end() const { return end_; }
    // Impacts, overturning and mode changes, increasing.
    const std::vector<double>& eventTimes() const { return events_; }
    // The state drawn at t (core's path, interpolated between its samples).
    RockingSample at(double t) const { return pathAt(path_.samples, t); }
    double baseAcceleration(double t) const; // a_h, g (0 without a pulse)
    bool overturnedBy(double t) const;
    // The impact at or just before t within `window` seconds (for a flash), or none.
    std::optional<double> impactNear(double t, double window) const;

private:
    BlockCase case_;
    RockingPath path_;
    std::string error_;
    double end_ = 1.0;
    std::vector<double> events_;
};

} // namespace kinstab::ui
