// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Axis ticks on 1-2-5 steps (0.1, 0.2, 0.5, 1, 2, 5, …), so labels read 0.6, 0.8, 1.0 rather
// than 0.56, 0.76, 0.96.

#include <vector>

namespace kinstab::ui {

struct NiceAxis {
    double min = 0, max = 1, step = 1; // min and max are multiples of step
    int segments() const;
    int decimals() const; // enough to tell the ticks apart
};

// The 1-2-5 step nearest to range / count: about `count` ticks (the teaching view's scales,
// where the tick count may overshoot a little).
double niceTickStep(double range, int count);
// The smallest 1-2-5 step giving at most maxTicks intervals over [lo, hi].
double niceStep(double lo, double hi, int maxTicks);
// [lo, hi] widened outwards to whole steps.
NiceAxis niceAxis(double lo, double hi, int maxTicks);
// The step multiples inside [lo, hi] (not widened).
std::vector<double> niceTicks(double lo, double hi, int maxTicks);

} // namespace kinstab::ui
