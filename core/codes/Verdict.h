// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Which limit a code's force reaches first (Furgerson 1980, ch. V): the members' strength
// (overstress) or the slab's critical amplitude (kinetic instability). Shared by the design check
// of the top floor (core/check/DesignCheck.h) and the floor-acceleration demands (FloorDemand.h).

#include <string>

namespace kinstab {

enum class Verdict { OverstressGoverns, KineticInstabilityGoverns };
std::string verdictText(Verdict v); // "overstress governs" | "kinetic instability governs"

} // namespace kinstab
