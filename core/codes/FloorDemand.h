// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A code's peak floor acceleration (PFA) demand on a rigid element supported at each level,
// in g, with the coefficient trail, and its verdict against the critical floor peak of the
// slab at its level. Below the critical peak the slab stays on its walls; at or above it the
// slab can slide off (the paper's "kinetic instability governs").

#include "core/codes/CodeResult.h"
#include "core/codes/Verdict.h"

#include <optional>
#include <string>
#include <vector>

namespace kinstab {

struct FloorDemand {
    std::string code; // "asce7_22" | "asce7_22_mce" | "ec8"
    std::string title;
    std::vector<double> zOverH;    // per level, bottom first
    std::vector<double> factor;    // the code's height factor per level (H_f, or S_a / alpha S)
    std::vector<double> pfa;       // g per level
    int slabLevel = 0;             // 1-based
    double slabPfa = 0;            // g, pfa at the slab's level
    std::vector<TrailEntry> trail; // coefficients used; level-dependent ones at the slab's level
    std::vector<std::string> notes;
};

struct FloorVerdict {
    std::string code;
    std::string title;
    double demand = 0;              // g, PFA at the slab's level
    std::optional<double> critical; // g, critical floor peak at that level; none: no collapse
    std::optional<double> margin;   // critical / demand
    Verdict verdict = Verdict::OverstressGoverns;
    std::string explanation;
};

// searchLimit: the critical search's limit (g), the bound when nothing collapsed; what: the
// critical value's name in the explanation.
FloorVerdict judgeFloorDemand(const FloorDemand& d, std::optional<double> critical,
                              double searchLimit, const std::string& what = "critical floor peak");

// The level's height over the building's height, bottom first.
std::vector<double> relativeLevelHeights(const Building& b);

} // namespace kinstab
