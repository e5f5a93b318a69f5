// SPDX-License-Identifier: GPL-3.0-or-later
// The impacts of a rocking run (Housner 1963) and the end of its rocking: the Zeno rest of dying
// rebounds, and the fate of free rocking once the base motion has ended (core/rocking/
// FreeRocking.h).
#include "core/rocking/FreeRocking.h"
#include "core/rocking/RockingRun.h"

namespace kinstab::blockrun {

// After an impact: is the rebound so small that the block is back at rest? Pulled back to its
// base with theta'' (the other corner's equation at theta = 0), a rebound theta' rises
// theta'^2 / (2 |theta''|), and the heights of all the bounces that follow sum to that over
// (1 - eta^2).
bool RockingRun::reboundDies() const {
    const double w = std::abs(y_[1]);
    if (w < kRestRebound * k_.p * k_.alpha) return true;
    const double acc = z_ * rockingAcceleration(k_, z_, 0.0, baseAt(t_));
    if (!(acc < 0.0) || !(eta_ < 1.0)) return false;
    return w * w / (-2.0 * acc) / (1.0 - eta_ * eta_) < kRestHeight * k_.alpha;
}

// theta = 0: the block lands on its base and rocks on about the other corner with its angular
// velocity times eta (Housner 1963); the corner's sliding, if any, goes on.
bool RockingRun::afterImpact() {
    r_.impactTimes.push_back(t_);
    y_[0] = 0.0;
    y_[1] *= eta_;
    z_ = -z_;
    if (t_ >= endT_) ++impactsAfterEnd_;
    if (!hasDuration_ && impactsAfterEnd_ >= kImpactsAfterEnd) stop_ = true;
    if (reboundDies()) {
        y_[1] = 0.0;
        if (y_[3] != 0.0) {
            sigma_ = sgn(y_[3]);
            return startMode(BlockMode::Slide);
        }
        return startMode(BlockMode::Rest);
    }
    if (mode_ == BlockMode::SlideRock && y_[3] != 0.0) {
        sigma_ = sgn(z_ * y_[3]);
        return startMode(BlockMode::SlideRock);
    }
    return startMode(BlockMode::Rock);
}

// After the base motion has ended, free rocking is decided by its energy (FreeRocking.h).
void RockingRun::decideFree() {
    if (decided_ || t_ < endT_ || mode_ != BlockMode::Rock || canSlide_) return;
    decided_ = true;
    const FreeFate fate =
        freeFate(k_.linear ? RockingEquations::Linearised : RockingEquations::Exact, k_.p, k_.alpha,
                 eta_, y_[0], y_[1]);
    if (fate.overturns) {
        overturned_ = true;
        if (o_.stopAtOverturnDecision && !o_.followOverturn) stop_ = true;
        return;
    }
    seeTheta(fate.maxAbsTheta);
    if (o_.stopAtOverturnDecision && !hasDuration_) stop_ = true;
}

} // namespace kinstab::blockrun
