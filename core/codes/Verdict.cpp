// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/codes/Verdict.h"

namespace kinstab {

std::string verdictText(Verdict v) {
    return v == Verdict::OverstressGoverns ? "overstress governs" : "kinetic instability governs";
}

bool slabHolds(double demand, std::optional<double> critical, double searchLimit) {
    return demand < critical.value_or(searchLimit);
}

Verdict verdictOf(double demand, std::optional<double> critical, double searchLimit) {
    return slabHolds(demand, critical, searchLimit) ? Verdict::OverstressGoverns
                                                    : Verdict::KineticInstabilityGoverns;
}

} // namespace kinstab
