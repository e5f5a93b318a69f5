// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Sweeps over an (amplitude, frequency) grid on all cores. Per point they keep only what a
// surface shows: the collapse time and the outcome (docs/theory.md §6.6, "leave out what a scene
// does not need"). A point function makes the same sweep serve every model.

#include "core/slab/PointResult.h"
#include "core/slab/Slab1DCase.h"
#include "core/sweep/Grid.h"
#include "core/sweep/SweepControl.h"

#include <functional>
#include <vector>

namespace kinstab {

// Results in row-major order: index = i * frequencies + j for amplitudes[i], frequencies[j].
struct SweepResult {
    SweepGrid grid;
    std::vector<PointResult> points;
    std::vector<unsigned char> done; // 1 where the point was computed (a cancel leaves holes)
    std::size_t completed = 0;
    bool cancelled = false;
    double wallTimeSeconds = 0;

    const PointResult& at(std::size_t i, std::size_t j) const {
        return points[i * grid.frequencies.size() + j];
    }
};

// threads <= 0: all hardware threads.
SweepResult runSweep(const SweepGrid& grid, const PointFunction& point,
                     SweepControl* control = nullptr, int threads = 0);

PointFunction slab1DPoint(const Slab1DCase& c);

// gamma_c over the grid (0 where not collapsed), same layout as SweepResult::points.
std::vector<double> collapseFactors(const SweepResult& r, double tauRef);

} // namespace kinstab
