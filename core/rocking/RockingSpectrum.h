// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The rocking spectrum of a record (Makris & Konstantinidis 2003): for blocks of one slenderness
// alpha, the largest |theta| / alpha against the frequency parameter p (i.e. the block's size,
// R = 3 g / (4 p^2)), with overturning marked; on core's thread pool.

#include "core/rocking/BaseMotion.h"
#include "core/rocking/RockingModel.h"
#include "core/sweep/SweepControl.h"

#include <vector>

namespace kinstab {

struct RockingSpectrumSpec {
    double alpha = 0.25;             // rad
    std::vector<double> frequencies; // p, rad/s, > 0
    int threads = 0;
};

struct RockingSpectrumPoint {
    double p = 0;
    double halfWidth = 0, halfHeight = 0; // m, the block of that p
    double maxThetaOverAlpha = 0;
    bool overturns = false;
};

// model gives restitution (none: Housner's of alpha), equations, mu; its block is replaced by
// the one of (alpha, p) for each point.
std::vector<RockingSpectrumPoint> rockingSpectrum(const RockingModel& model,
                                                  const BaseMotion& motion,
                                                  const RockingSpectrumSpec& spec,
                                                  const SweepControl* control = nullptr);

} // namespace kinstab
