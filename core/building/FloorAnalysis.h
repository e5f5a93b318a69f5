// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The floor-motion check of a project, shared by `kinstab-cli floors`, the GUI's Floors view and
// the report: the shear-building model of the building, every level's motion under a ground
// record, the codes' floor-acceleration demands (ASCE 7-22 §13.3.1, EN 1998-1 §4.3.5.2) per
// level, the critical PGA per level, and, for
// comparison at the roof, the paper's SDOF floor filter (period T, the same damping). The checks
// at the slab's level are the assessment's (core/assessment/Assessment.h: floors.CODE.LEVEL).

#include "core/building/FloorMotions.h"
#include "core/building/FloorSettings.h"
#include "core/building/LevelCritical.h"
#include "core/codes/CodeSet.h"
#include "core/codes/FloorDemand.h"

#include <optional>
#include <string>
#include <vector>

namespace kinstab {

struct FloorAnalysisInput {
    Building building;
    CodeSelection codes; // ASCE 7-22 and EC8 inputs give their demands; others are ignored
    FloorSettings settings;
    Slab1DCase slab;
    CriticalSearch search;
    Accelerogram ground;  // the ground record as recorded
    bool critical = true; // search the critical PGA of every level
};

struct FloorAnalysis {
    ShearBuilding building;
    ModalModel model;
    std::vector<Accelerogram> motions;   // per level, bottom first
    std::vector<double> pfa;             // g per level, the record as given
    double pga = 0;                      // g, |peak| of the ground record
    int slabLevel = 0;                   // 1-based
    std::vector<FloorDemand> demands;    // asce7_22, asce7_22_mce, ec8 (those the codes select)
    std::vector<LevelCritical> critical; // per level when searched
    double sdofRoofPeak = 0;             // g, the floor filter's (T, damping) peak
    double damping = 0.05;               // modal damping used (and the filter's)
    bool cancelled = false;
};

// Empty when fine, else a message naming the field and the value.
std::string validateFloorAnalysis(const FloorAnalysisInput& in);
// Throws std::invalid_argument (InputError for the building and codes) on bad input.
FloorAnalysis analyseFloors(const FloorAnalysisInput& in, SweepControl* control = nullptr);

// The demands alone (no record needed): asce7_22, asce7_22_mce, ec8 as the codes select.
std::vector<FloorDemand> floorDemands(const Building& b, const CodeSelection& codes,
                                      const FloorSettings& s);

} // namespace kinstab
