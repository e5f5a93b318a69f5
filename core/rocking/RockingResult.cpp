// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/rocking/RockingResult.h"

#include "core/base/NameTable.h"

namespace kinstab {

// BlockMode's names, in its declaration order (Rest, Slide, Rock, SlideRock).
constexpr std::array<const char*, 4> kBlockModeNames = {"rest", "slide", "rock", "slide-rock"};
static_assert(kBlockModeNames.size() == static_cast<std::size_t>(BlockMode::SlideRock) + 1);

std::string_view blockModeName(BlockMode m) {
    return enumName(kBlockModeNames, m);
}

// RockingOutcome's names, in its declaration order (Rest, Slides, Rocks, SlideRock, Overturns,
// LeavesBase).
constexpr std::array<const char*, 6> kRockingOutcomeNames = {
    "rest", "slides", "rocks", "slide-rock", "overturns", "leaves-base"};
static_assert(kRockingOutcomeNames.size() ==
              static_cast<std::size_t>(RockingOutcome::LeavesBase) + 1);

std::string_view rockingOutcomeName(RockingOutcome o) {
    return enumName(kRockingOutcomeNames, o);
}

} // namespace kinstab
