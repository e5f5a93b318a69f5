// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/StudyRow.h"

#include "core/base/TextInput.h"

#include <nlohmann/json.hpp>

namespace kinstab {

using ojson = nlohmann::ordered_json;

namespace {
ojson orNull(const std::optional<double>& v) {
    return v ? ojson(*v) : ojson();
}

double number(const nlohmann::json& j, const char* key) {
    if (!j.contains(key) || !j[key].is_number())
        throw StudyRowError(std::string("\"") + key + "\": expected a number");
    return j[key].get<double>();
}

std::optional<double> optionalNumber(const nlohmann::json& j, const char* key) {
    if (!j.contains(key) || j[key].is_null()) return std::nullopt;
    return number(j, key);
}

std::size_t count(const nlohmann::json& j, const char* key) {
    if (!j.contains(key) || !j[key].is_number_unsigned())
        throw StudyRowError(std::string("\"") + key + "\": expected a count");
    return j[key].get<std::size_t>();
}

std::optional<std::string> optionalText(const nlohmann::json& j, const char* key) {
    if (!j.contains(key) || j[key].is_null()) return std::nullopt;
    if (!j[key].is_string()) throw StudyRowError(std::string("\"") + key + "\": expected a string");
    return j[key].get<std::string>();
}

std::string text(const nlohmann::json& j, const char* key) {
    if (!j.contains(key) || !j[key].is_string())
        throw StudyRowError(std::string("\"") + key + "\": expected a string");
    return j[key].get<std::string>();
}
} // namespace

std::string studyDriverText(const StudyRow& r) {
    std::string s = "ground";
    if (r.level)
        s = "level " + std::to_string(*r.level);
    else if (r.floorPeriod)
        s = "floor T = " + formatDouble(*r.floorPeriod) +
            " s, ζ = " + formatDouble(r.floorDamping.value_or(0.0));
    if (r.motion && *r.motion == "fitted_sine") s += ", fitted sine";
    return s;
}

// nlohmann's dump writes the shortest text that reads back as the same double, in the C
// locale's syntax whatever the process locale: the same bytes on every machine and rerun.
std::string studyRowLine(const StudyRow& r) {
    ojson j = {{"case", r.index},
               {"cases", r.cases},
               {"set", r.set},
               {"record", r.record},
               {"mu", r.mu},
               {"tstar", r.tstar},
               {"limit", r.limit},
               {"floor_period_s", orNull(r.floorPeriod)},
               {"floor_damping", orNull(r.floorDamping)}};
    if (r.level) j["level"] = *r.level;
    if (r.motion) j["motion"] = *r.motion;
    j["measure"] = r.measure;
    j["record_im_g"] = r.recordIntensity;
    if (r.scale) {
        j["scale"] = *r.scale;
        j["im_as_given_g"] = r.imAsGiven;
    }
    j["critical_im_g"] = orNull(r.criticalIntensity);
    j["critical_peak_g"] = orNull(r.criticalPeak);
    j["limit_im_g"] = r.limitIntensity;
    if (r.scale) {
        j["collapses_as_given"] = r.collapsesAsGiven;
        j["margin"] = orNull(r.margin);
    }
    if (!r.noFit.empty()) j["no_fit"] = r.noFit;
    j["runs"] = r.runs;
    return j.dump();
}

StudyRow parseStudyRow(const std::string& line) {
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (j.is_discarded() || !j.is_object()) throw StudyRowError("not a JSON object");
    StudyRow r;
    r.index = count(j, "case");
    r.cases = count(j, "cases");
    r.set = count(j, "set");
    r.record = text(j, "record");
    r.mu = number(j, "mu");
    r.tstar = number(j, "tstar");
    r.limit = number(j, "limit");
    r.floorPeriod = optionalNumber(j, "floor_period_s");
    r.floorDamping = optionalNumber(j, "floor_damping");
    r.measure = text(j, "measure");
    r.recordIntensity = number(j, "record_im_g");
    r.criticalIntensity = optionalNumber(j, "critical_im_g");
    r.criticalPeak = optionalNumber(j, "critical_peak_g");
    r.limitIntensity = number(j, "limit_im_g");
    r.runs = static_cast<long>(count(j, "runs"));
    if (j.contains("level")) {
        const std::size_t level = count(j, "level");
        if (level < 1 || level > 1000) throw StudyRowError("\"level\": expected 1 to 1000");
        r.level = static_cast<int>(level);
    }
    r.motion = optionalText(j, "motion");
    r.noFit = optionalText(j, "no_fit").value_or("");
    r.scale = optionalNumber(j, "scale");
    if (r.scale) {
        r.imAsGiven = number(j, "im_as_given_g");
        if (!j.contains("collapses_as_given") || !j["collapses_as_given"].is_boolean())
            throw StudyRowError("\"collapses_as_given\": expected true or false");
        r.collapsesAsGiven = j["collapses_as_given"].get<bool>();
        r.margin = optionalNumber(j, "margin");
    }
    if (r.index >= r.cases) throw StudyRowError("\"case\": not below \"cases\"");
    return r;
}

} // namespace kinstab
