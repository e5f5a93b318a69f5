// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The checks of the free-standing blocks a project names (core/rocking/FreeBlock.h): per block
// and code level, the ground PGA at which the block on its level overturns against the ground
// acceleration the code level implies — the same intensities as the slab's floor checks
// (docs/assessment.md, "Why the floor checks compare ground intensities"), with the code's own
// floor formula (its PFA at the block's level against the critical floor peak) as the second
// comparison. The building is linear, so the critical scale of the level's motion (the
// overturning search of core/rocking/OverturningAmplitude.h over that motion scaled to a peak)
// gives the critical ground PGA as critical floor peak x |PGA| / |floor peak|.

#include "core/assessment/Check.h"
#include "core/codes/FloorDemand.h"
#include "core/records/Accelerogram.h"
#include "core/rocking/FreeBlock.h"
#include "core/sweep/SweepControl.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace kinstab {

struct Project;

// What one block's checks need: the code demands at its level and its overturning search.
struct BlockCheckPart {
    FreeBlock block;
    int level = 0;                    // 1-based, resolved (the roof when the block names none)
    int stories = 0;                  //
    std::vector<FloorDemand> demands; // asce7_22, asce7_22_mce, ec8 at the block's level
    double pga = 0;                   // g, |peak| of the ground record as given
    double floorPeak = 0;             // g, |peak| of the level's motion, record as given
    std::optional<double> criticalFloorPeak; // g; none: no overturning up to searchLimit
    std::optional<double> criticalPga;       // g, the ground record's peak at that overturning
    std::vector<std::pair<double, double>> intervals; // overturning floor peaks (g), increasing
    double searchLimit = 0;                           // g, of the floor peak
    long runs = 0;
};

// The overturning search of every block of the project on its level of the building's shear
// model (the project's floor settings, defaults when none) under the ground record. A block of
// a project without a code floor demand (neither asce7_22 nor ec8) gets no demands. A cancel
// stops between runs; the caller checks control. Throws std::invalid_argument / InputError on
// bad input (the building cannot carry floor motions).
std::vector<BlockCheckPart> blockCheckParts(const Project& p, const Accelerogram& ground,
                                            const SweepControl* control = nullptr);

// One check per code demand of the part ("block.NAME.asce7_22.design", ...).
std::vector<Check> blockChecks(const BlockCheckPart& part, const std::string& recordName);

// "block.parapet": the prefix of a block's check ids.
std::string blockCheckPrefix(const FreeBlock& b);

// "b = 0.1 m, h = 0.6 m (alpha = 0.1651 rad, p = 3.75 rad/s), mu = 0.6, Housner's
// restitution 0.959, exact equations": the model in words (the checks' model text).
std::string blockModelText(const FreeBlock& b);

} // namespace kinstab
