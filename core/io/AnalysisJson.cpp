// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/AnalysisJson.h"

#include "core/base/ModelKind.h"
#include "core/io/CaseJson.h"
#include "core/io/JsonValue.h"

#include <optional>

namespace kinstab {

using nlohmann::json;

json requestModelJson(const AnalysisRequest& q) {
    if (const std::optional<PlanarCase> c = q.planarCase()) return planarCaseJson(*c);
    return {{"model", modelKindName(ModelKind::Slab1D)},
            {"solver", solverName(q.slab.solver)},
            {"envelope", envelopeJson(q.slab)},
            {"mu", q.slab.slab.mu},
            {"tstar", q.slab.tstar}};
}

json criticalSearchJson(const CriticalSearch& s) {
    return {{"max_amplitude", s.to}, {"scan_step", s.scanStep}, {"tolerance", s.tolerance}};
}

json criticalCurveJson(const AnalysisRequest& q, const CriticalCurve& c) {
    json a = json::array();
    for (const std::optional<double>& amplitude : c.amplitude)
        a.push_back(orNull(amplitude));
    json j = requestModelJson(q);
    j.update({{"frequencies", q.criticalFrequencies}, {"a_crit", a}});
    j.update(criticalSearchJson(q.criticalSearch));
    return j;
}

} // namespace kinstab
