// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/slab/SlabTypes.h"

#include "core/base/NameTable.h"
#include "core/slab/SlabInputs.h"

#include <cmath>
#include <sstream>

namespace kinstab {

// Outcome's names, in its declaration order (Collapsed, Stable, LiftOff, Failed).
constexpr std::array<const char*, 4> kOutcomeNames = {"collapsed", "stable", "lift_off", "failed"};
static_assert(kOutcomeNames.size() == static_cast<std::size_t>(Outcome::Failed) + 1);

std::string outcomeName(Outcome o) {
    return enumName(kOutcomeNames, o);
}

// ExitSide's names, in its declaration order (None, Across, Along).
constexpr std::array<const char*, 3> kExitSideNames = {"none", "across", "along"};
static_assert(kExitSideNames.size() == static_cast<std::size_t>(ExitSide::Along) + 1);

std::string exitSideName(ExitSide s) {
    return enumName(kExitSideNames, s);
}

// EventKind's names, in its declaration order (SlipOnset, Stick, Reversal, Collapse, Stable,
// DurationCap, LiftOff).
constexpr std::array<const char*, 7> kEventKindNames = {
    "slip", "stick", "reversal", "collapse", "stable", "duration_cap", "lift_off"};
static_assert(kEventKindNames.size() == static_cast<std::size_t>(EventKind::LiftOff) + 1);

std::string eventKindName(EventKind k) {
    return enumName(kEventKindNames, k);
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
