// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The exact 1-DOF solver's stop search keeps its last evaluation (core/slab/ExactSolver.cpp):
// the stop lies within the search's last Halley step of it (about 1e-9), so the slip's state at
// the stop follows from it by Taylor's series, without a closed-form evaluation at the stop
// (docs/theory.md §6.3).

#include "core/excitation/Excitation1D.h"

#include <cmath>
#include <limits>

namespace kinstab {

// The last point the stop search evaluated: tau, the slip velocity v, and a, a', a'' there.
struct StopSample {
    double tau = std::numeric_limits<double>::quiet_NaN(), v = 0;
    AccelAt at;
    // Whether the stop at tStop is near enough for stateAt(): a step of at most 1e-6 (the next
    // term of the series, a'' h^4 / 24, is then far below a rounding of x) and a'' known (not a
    // record's, not a stop at the slip's start, where no search ran).
    bool reaches(double tStop) const {
        return std::abs(tStop - tau) <= 1e-6 && !std::isnan(at.d2a);
    }
    // The displacement at tStop from x0 there, with slip sign s against friction mu
    // (v' = -s mu - a, v'' = -a'), and a at tStop.
    double displacementAt(double tStop, double x0, int s, double mu) const {
        const double h = tStop - tau, dv = -s * mu - at.a;
        return x0 + h * (v + h * (0.5 * dv - h * at.da / 6.0));
    }
    double accelAt(double tStop) const {
        const double h = tStop - tau;
        return at.a + h * (at.da + 0.5 * h * at.d2a);
    }
};

} // namespace kinstab
