// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A code's peak floor acceleration (PFA) demand on a rigid element supported at each level,
// in g, with the coefficient trail, and the ground acceleration the code level implies. The
// checks against the slab's critical floor peak and critical ground PGA are the assessment's
// (core/assessment/Assessment.h).

#include "core/codes/CodeResult.h"

#include <optional>
#include <string>
#include <vector>

namespace kinstab {

struct FloorDemand {
    std::string code; // "asce7_22" | "asce7_22_mce" | "ec8"
    std::string title;
    std::vector<double> zOverH; // per level, bottom first
    std::vector<double> factor; // the code's height factor per level (H_f, or S_a / alpha S)
    std::vector<double> pfa;    // g per level
    int slabLevel = 0;          // 1-based
    double slabPfa = 0;         // g, pfa at the slab's level
    // g, the ground acceleration the code level implies: the same expression at grade (ASCE 7-22
    // §13.3.1 with H_f = 1 and R_mu = 1 as §13.3.1.1 sets below grade: 0.4 S_DS, or 0.4 S_MS at
    // MCE_R; EN 1998-1 eq. 4.25 at z = 0 for a rigid element: alpha S).
    double groundPga = 0;
    std::string groundPgaSource;   // "0.4 S_MS", "alpha S"
    std::vector<TrailEntry> trail; // coefficients used; level-dependent ones at the slab's level
    std::vector<std::string> notes;
};

// The level's height over the building's height, bottom first.
std::vector<double> relativeLevelHeights(const Building& b);

} // namespace kinstab
