// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/StudyJson.h"
#include "core/io/StudySpecJson.h"

#include "core/base/TextInput.h"
#include "core/io/MotionJson.h"
#include "core/study/StudySpec.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace kinstab {

using nlohmann::json;

namespace {
// A path longer than any file system allows is a typing accident, not a file.
constexpr std::size_t kMaxStudyPathChars = 4096;

std::string pathFrom(const JsonReader& r, const std::string& key, const std::string& baseDir) {
    const std::string text = r.pathText(key, "");
    if (text.size() > kMaxStudyPathChars)
        r.fail(key, std::to_string(text.size()) + " characters, more than the limit of " +
                        std::to_string(kMaxStudyPathChars));
    return pathFromProject(text, baseDir);
}

// A number of the hazard block in [lo, hi] (lo excluded when openLow), or a message naming it;
// the same ranges as kinstab-cli risk's (core/risk/RiskRequest.cpp).
double rangedNumber(const JsonReader& r, const std::string& key, double fallback, double lo,
                    double hi, bool openLow, const std::string& unit) {
    const double x = r.number(key, fallback);
    const bool low = openLow ? !(x > lo) : !(x >= lo);
    if (!std::isfinite(x) || low || x > hi)
        r.fail(key, formatDouble(x) + ": must be " + (openLow ? "> " : ">= ") + formatDouble(lo) +
                        " and at most " + formatDouble(hi) + unit);
    return x;
}

std::pair<double, double> siteFrom(const JsonReader& h) {
    const nlohmann::json& j = h.raw("site");
    if (!j.is_array() || j.size() != 2 || !j[0].is_number() || !j[1].is_number())
        h.fail("site", "expected [longitude, latitude] in degrees, got " + j.dump());
    const double lon = j[0].get<double>(), lat = j[1].get<double>();
    if (!(lon >= -180 && lon <= 360))
        h.fail("site", "longitude " + formatDouble(lon) + ": must be >= -180 and at most 360");
    if (!(lat >= -90 && lat <= 90))
        h.fail("site", "latitude " + formatDouble(lat) + ": must be >= -90 and at most 90");
    return {lon, lat};
}

std::optional<ProjectHazard> hazardFrom(const JsonReader& s, const std::string& baseDir) {
    if (!s.has("hazard")) return std::nullopt;
    const JsonReader h = s.object("hazard");
    ProjectHazard out;
    out.file = pathFrom(h, "file", baseDir);
    if (out.file.empty()) h.fail("file", "missing: the path of the hazard curve");
    out.format = h.text("format", "auto");
    if (std::find(std::begin(kProjectHazardFormats), std::end(kProjectHazardFormats), out.format) ==
        std::end(kProjectHazardFormats))
        h.fail("format", quotedToken(out.format) + ": must be auto, openquake, usgs or csv");
    if (h.has("site")) out.site = siteFrom(h);
    if (h.has("target_rate"))
        out.targetRate = rangedNumber(h, "target_rate", 0, 0.0, 1.0, true, " per year");
    out.years = rangedNumber(h, "years", 50, 0.0, kMaxProjectHazardYears, true, " years");
    return out;
}

StudySpec loadStudyFor(const ProjectStudy& s) {
    try {
        return loadStudy(s.spec);
    } catch (const StudyError& e) {
        throw JsonFieldError("study.spec = " + quotedToken(s.spec) + ": " + e.what());
    }
}
} // namespace

json studyToJson(const ProjectStudy& s, const std::string& baseDir) {
    json j = {{"spec", pathForProject(s.spec, baseDir)}};
    if (!s.results.empty()) j["results"] = pathForProject(s.results, baseDir);
    if (const auto& h = s.hazard) {
        json hj = {{"file", pathForProject(h->file, baseDir)}, {"format", h->format}};
        if (h->site) hj["site"] = {h->site->first, h->site->second};
        if (h->targetRate) hj["target_rate"] = *h->targetRate;
        hj["years"] = h->years;
        j["hazard"] = hj;
    }
    return j;
}

std::optional<ProjectStudy> studyFromJson(const JsonReader& r, const std::string& baseDir) {
    if (!r.has("study") || r.raw("study").is_null()) return std::nullopt;
    const JsonReader s = r.object("study");
    ProjectStudy out;
    out.spec = pathFrom(s, "spec", baseDir);
    if (out.spec.empty()) s.fail("spec", "missing: the path of the study file");
    out.results = pathFrom(s, "results", baseDir);
    out.hazard = hazardFrom(s, baseDir);
    return out;
}

void checkStudyFile(const ProjectStudy& s) {
    (void)loadStudyFor(s);
}

} // namespace kinstab
