// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Which limit a code's force reaches first (Furgerson 1980, ch. V): the members' strength
// (overstress) or the slab's critical amplitude (kinetic instability). Shared by the design check
// of the top floor (core/check/DesignCheck.h) and the floor-acceleration demands (FloorDemand.h).

#include <optional>
#include <string>

namespace kinstab {

enum class Verdict { OverstressGoverns, KineticInstabilityGoverns };
std::string verdictText(Verdict v); // "overstress governs" | "kinetic instability governs"

// Chapter V's rule, the one every check applies: the slab holds at a demand below its critical
// intensity, or below the search's limit when nothing up to it collapses.
bool slabHolds(double demand, std::optional<double> critical, double searchLimit);
// The verdict of that rule: the members overstress first when the slab holds.
Verdict verdictOf(double demand, std::optional<double> critical, double searchLimit);

} // namespace kinstab
