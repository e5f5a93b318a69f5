// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/codes/FloorDemand.h"

#include <sstream>

namespace kinstab {

FloorVerdict judgeFloorDemand(const FloorDemand& d, std::optional<double> critical,
                              double searchLimit, const std::string& what) {
    FloorVerdict v;
    v.code = d.code;
    v.title = d.title;
    v.demand = d.slabPfa;
    v.critical = critical;
    std::ostringstream s;
    s << "PFA demand at level " << d.slabLevel << " = " << d.slabPfa << " g";
    if (!critical) {
        v.verdict = d.slabPfa < searchLimit ? Verdict::OverstressGoverns
                                            : Verdict::KineticInstabilityGoverns;
        s << "; " << what << ": no collapse up to " << searchLimit << " g";
    } else {
        if (d.slabPfa > 0) v.margin = *critical / d.slabPfa;
        v.verdict =
            d.slabPfa < *critical ? Verdict::OverstressGoverns : Verdict::KineticInstabilityGoverns;
        s << (d.slabPfa < *critical ? " < " : " >= ") << what << " = " << *critical << " g";
    }
    v.explanation = s.str();
    return v;
}

std::vector<double> relativeLevelHeights(const Building& b) {
    std::vector<double> z = levelHeights(b);
    for (double& x : z)
        x /= b.height;
    return z;
}

} // namespace kinstab
