// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/assessment/AssessmentRunJson.h"

#include "core/assessment/AssessmentJson.h"
#include "core/io/AnalysisJson.h"
#include "core/io/CheckJson.h"
#include "core/io/CodesJson.h"

namespace kinstab {

nlohmann::json assessmentRunJson(const Project& p, const AssessmentRun& run, double wallSeconds) {
    nlohmann::json j = run.record ? recordCheckJson(*run.record, p.record->floor)
                                  : designCheckJson(*run.parts.sine);
    j["assessment"] = assessmentJson(run.assessment);
    j["project"] = p.name;
    j.update(requestModelJson(run.request));
    if (p.record) j.erase("envelope");
    j["search"] = criticalSearchJson(p.critical);
    j["wall_time_s"] = wallSeconds;
    return j;
}

} // namespace kinstab
