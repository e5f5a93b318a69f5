// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One picked point of a planar surface, run again with its path recorded (a sweep keeps only
// tau_c, the outcome and the exit side): the relative displacements δx (across) and δy (along
// the walls) against τ.

#include "core/slab/PlanarCase.h"

namespace kinstab::ui {

struct PlanarPointRun : RunPoint {
    double limit = 1, theta = 20;
    PlanarResult result;
    std::vector<PlanarSample> path; // every accepted step and event
};

PlanarPointRun runPlanarPoint(const PlanarCase& c, double amplitude, double frequencyHz);

} // namespace kinstab::ui
