// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/StudyFileWriter.h"

#include "core/study/StudySpec.h"

namespace kinstab {

namespace {

using nlohmann::json;

// base's object under key, or an empty object when it has none (or something else there).
json objectOf(const json& base, const char* key) {
    const json v = base.is_object() ? base.value(key, json::object()) : json::object();
    return v.is_object() ? v : json::object();
}

json recordsOf(const StudyFileFields& f) {
    if (f.openedRecords) return *f.openedRecords;
    return json::array({{{"path", f.folder}, {"include", f.include}, {"exclude", f.exclude}}});
}

json intensityOf(const json& base, const StudyFileFields& f) {
    json im = objectOf(base, "intensity");
    im["measure"] = f.measure;
    if (f.measure == "sa") im["period_s"] = f.saPeriodS;
    if (f.measure == "pga") im.erase("period_s");
    return im;
}

json parametersOf(const json& base, const StudyFileFields& f) {
    json p = objectOf(base, "parameters");
    // A block study has no slab: the file refuses mu and t* there (the block keeps its own).
    if (!(base.is_object() && base.contains("block"))) {
        p["mu"] = f.mu;
        p["tstar"] = f.tstar;
        p.erase("wall_width_in"); // the field is t*
    }
    if (!f.floorPeriods) {
        p.erase("floor_filter");
    } else {
        if (!p.contains("floor_filter") || !p["floor_filter"].is_object())
            p["floor_filter"] = json::object();
        p["floor_filter"]["periods_s"] = *f.floorPeriods;
    }
    return p;
}

} // namespace

std::string studyFileText(const nlohmann::json& base, const StudyFileFields& f) {
    json study = base.is_object() ? base : json::object();
    study["format"] = kStudyFormat;
    study["version"] = kStudyVersion;
    study["records"] = recordsOf(f);
    study["intensity"] = intensityOf(base, f);
    study["parameters"] = parametersOf(base, f);
    json search = objectOf(base, "search");
    search["max_g"] = f.maxG;
    search["scan_step_g"] = f.scanStepG;
    study["search"] = search;
    return study.dump(2);
}

} // namespace kinstab
