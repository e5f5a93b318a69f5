// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/CheckJson.h"

#include "core/io/CodesJson.h"
#include "core/io/JsonValue.h"
#include "core/io/RecordJson.h"

namespace kinstab {

nlohmann::json recordCheckJson(const RecordAnalysis& a,
                               const std::optional<FloorFilterParams>& floor) {
    nlohmann::json j = designCheckJson(DesignCheckResult{a.verdicts, a.critical->runs});
    j["record"] = accelerogramJson(a.ground);
    j["floor_filter"] = floor ? floorFilterJson(*floor) : nlohmann::json();
    j["amplitude"] = a.peak;
    j["critical_peak_g"] = orNull(a.critical->peak);
    j["outcome"] = outcomeName(a.run.outcome);
    return j;
}

} // namespace kinstab
