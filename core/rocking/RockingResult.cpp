// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/rocking/RockingResult.h"

namespace kinstab {

std::string_view blockModeName(BlockMode m) {
    switch (m) {
    case BlockMode::Rest:
        return "rest";
    case BlockMode::Slide:
        return "slide";
    case BlockMode::Rock:
        return "rock";
    case BlockMode::SlideRock:
        return "slide-rock";
    }
    return "rest";
}

std::string_view rockingOutcomeName(RockingOutcome o) {
    switch (o) {
    case RockingOutcome::Rest:
        return "rest";
    case RockingOutcome::Slides:
        return "slides";
    case RockingOutcome::Rocks:
        return "rocks";
    case RockingOutcome::SlideRock:
        return "slide-rock";
    case RockingOutcome::Overturns:
        return "overturns";
    case RockingOutcome::LeavesBase:
        return "leaves-base";
    }
    return "rest";
}

} // namespace kinstab
