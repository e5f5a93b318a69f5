// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/rocking/RockingPath.h"

#include "core/rocking/RockingSolver.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace kinstab {

RockingPath recordRocking(const RockingModel& model, const BaseMotion& motion,
                          double sampleInterval) {
    if (!(sampleInterval > 0.0))
        throw std::invalid_argument("recordRocking: the sample interval must be > 0");
    RockingPath path;
    RockingRunOptions o;
    o.sampleInterval = sampleInterval;
    o.recorder = [&path](const RockingSample& s) { path.samples.push_back(s); };
    path.result = simulateRocking(model, motion, o);
    // The recorder's last sample lies on its grid before the overturning time; the result says
    // where the fall ends: |theta| = pi/2 at overturnTime (RockingSolver.h).
    const auto& over = path.result.overturnTime;
    if (over && !path.samples.empty() && path.samples.back().t < *over) {
        RockingSample end = path.samples.back();
        end.t = *over;
        end.theta = std::copysign(std::numbers::pi / 2, end.theta);
        path.samples.push_back(end);
    }
    return path;
}

RockingSample pathAt(const std::vector<RockingSample>& samples, double t) {
    if (samples.empty()) return RockingSample{t};
    if (t <= samples.front().t) return samples.front();
    if (t >= samples.back().t) return samples.back();
    // The first sample after t; the one before it lies at or before t.
    const auto after = std::upper_bound(samples.begin(), samples.end(), t,
                                        [](double x, const RockingSample& s) { return x < s.t; });
    const RockingSample& b = *after;
    const RockingSample& a = *(after - 1);
    if (a.t == t || b.t == a.t) return a;
    const double w = (t - a.t) / (b.t - a.t);
    RockingSample s = a;
    s.t = t;
    s.theta = a.theta + w * (b.theta - a.theta);
    s.omega = a.omega + w * (b.omega - a.omega);
    s.sliding = a.sliding + w * (b.sliding - a.sliding);
    return s;
}

} // namespace kinstab
