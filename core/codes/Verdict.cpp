// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/codes/Verdict.h"

namespace kinstab {

std::string verdictText(Verdict v) {
    return v == Verdict::OverstressGoverns ? "overstress governs" : "kinetic instability governs";
}

} // namespace kinstab
