// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/teaching/BlockRun.h"

#include "core/rocking/BaseMotion.h"

#include <algorithm>

namespace kinstab::ui {

BlockRun::BlockRun(const BlockCase& c) : case_(c) {
    try {
        if (c.pulse)
            path_ = recordRocking(c.model, PulseMotion(*c.pulse), kBlockSampleInterval);
        else
            path_ = recordRocking(c.model, NoMotion(), kBlockSampleInterval);
    } catch (const std::exception& e) {
        error_ = e.what();
        path_ = RockingPath{};
    }
    end_ = path_.samples.empty() ? 1.0 : path_.samples.back().t;
    if (c.pulse) end_ = std::max(end_, c.pulse->length());
    end_ = std::max(end_, 0.1);
    events_ = path_.result.impactTimes;
    if (path_.result.overturnTime) events_.push_back(*path_.result.overturnTime);
    for (std::size_t k = 1; k < path_.samples.size(); ++k)
        if (path_.samples[k].mode != path_.samples[k - 1].mode)
            events_.push_back(path_.samples[k].t);
    std::sort(events_.begin(), events_.end());
    events_.erase(std::unique(events_.begin(), events_.end()), events_.end());
}

double BlockRun::alpha() const {
    return blockAlpha(case_.model.block);
}

double BlockRun::p() const {
    return blockFrequency(case_.model.block);
}

double BlockRun::baseAcceleration(double t) const {
    return case_.pulse ? PulseMotion(*case_.pulse).horizontal(t) : 0.0;
}

bool BlockRun::overturnedBy(double t) const {
    return path_.result.overturnTime && t >= *path_.result.overturnTime;
}

std::optional<double> BlockRun::impactNear(double t, double window) const {
    const auto& v = path_.result.impactTimes;
    const auto it = std::upper_bound(v.begin(), v.end(), t);
    if (it == v.begin()) return std::nullopt;
    const double ti = *(it - 1);
    return t - ti <= window ? std::optional<double>(ti) : std::nullopt;
}

} // namespace kinstab::ui
