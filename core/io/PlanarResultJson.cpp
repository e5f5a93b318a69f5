// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/PlanarResultJson.h"

#include "core/io/ResultJson.h"

namespace kinstab {

using nlohmann::json;

json planarResultJson(const PlanarResult& r, double tauRef) {
    json j = slabResultJson(r.slab, tauRef);
    j["exit_side"] = r.slab.outcome == Outcome::Collapsed ? json(exitSideName(r.exitSide)) : json();
    j["tau_lift_off"] = numberOrNull(r.tauLiftOff);
    j["max_abs_delta_y"] = r.maxAbsDeltaY;
    j["residual_delta_y"] = r.residualDeltaY;
    j["work"]["rejected_steps"] = r.slab.work.restarts;
    return j;
}

json planarEventsJson(const std::vector<PlanarEvent>& events) {
    json a = json::array();
    for (const PlanarEvent& e : events)
        a.push_back({{"tau", e.tau},
                     {"kind", eventKindName(e.kind)},
                     {"dx", e.dx},
                     {"dy", e.dy},
                     {"ux", e.ux},
                     {"uy", e.uy}});
    return a;
}

} // namespace kinstab
