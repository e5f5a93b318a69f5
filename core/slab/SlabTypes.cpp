// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/slab/SlabTypes.h"
#include "core/slab/SlabInputs.h"

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

InputProblem checkSlabParams(const SlabParams& p) {
    if (InputProblem e = checkInput(kMuInput, p.mu); !e.empty()) return e;
    if (InputProblem e = checkInput(kLimitInput, p.limit); !e.empty()) return e;
    if (p.duration) return checkInput(kDurationInput, *p.duration);
    return {};
}

std::string validateSlabParams(const SlabParams& p) {
    return describe(checkSlabParams(p));
}

} // namespace kinstab
