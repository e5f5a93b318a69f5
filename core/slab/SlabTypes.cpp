// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/slab/SlabTypes.h"
#include "core/slab/SlabLimits.h"

#include <cmath>
#include <sstream>

namespace kinstab {

std::string outcomeName(Outcome o) {
    switch (o) {
    case Outcome::Collapsed:
        return "collapsed";
    case Outcome::Stable:
        return "stable";
    case Outcome::LiftOff:
        return "lift_off";
    case Outcome::Failed:
        return "failed";
    }
    return "failed";
}

std::string exitSideName(ExitSide s) {
    switch (s) {
    case ExitSide::Across:
        return "across";
    case ExitSide::Along:
        return "along";
    case ExitSide::None:
        return "none";
    }
    return "none";
}

std::string eventKindName(EventKind k) {
    switch (k) {
    case EventKind::SlipOnset:
        return "slip";
    case EventKind::Stick:
        return "stick";
    case EventKind::Reversal:
        return "reversal";
    case EventKind::Collapse:
        return "collapse";
    case EventKind::Stable:
        return "stable";
    case EventKind::DurationCap:
        return "duration_cap";
    case EventKind::LiftOff:
        return "lift_off";
    }
    return "?";
}

std::string validateSlabParams(const SlabParams& p) {
    std::ostringstream s;
    if (!kMuRange.contains(p.mu))
        s << "mu = " << p.mu << ": friction coefficient must be between " << kMuRange.lo << " and "
          << kMuRange.hi;
    else if (!kSlipLimitRange.contains(p.limit))
        s << "limit = " << p.limit << ": bearing limit (bearing / (d/2)) must be > 0";
    else if (p.duration && (!std::isfinite(*p.duration) || *p.duration <= 0.0))
        s << "duration = " << *p.duration << ": tau_out must be a positive number";
    return s.str();
}

} // namespace kinstab
