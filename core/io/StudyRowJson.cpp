// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/StudyRowJson.h"

#include "core/base/TextInput.h"
#include "core/io/JsonValue.h"
#include "core/io/StudyBlockJson.h"
#include "core/study/StudyFingerprint.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <tuple>
#include <utility>

namespace kinstab {

using ojson = nlohmann::ordered_json;

namespace {

double number(const nlohmann::json& j, const char* key) {
    if (!j.contains(key) || !j[key].is_number())
        throw StudyRowError(std::string("\"") + key + "\": expected a number");
    const double x = j[key].get<double>();
    if (!std::isfinite(x)) throw StudyRowError(std::string("\"") + key + "\": not finite");
    return x;
}

// Every number of a row but the counts is a physical quantity > 0: a friction coefficient,
// t*, a limit, a period, damping, an intensity or a scale. Zero or less is a broken row.
double positive(const nlohmann::json& j, const char* key) {
    const double x = number(j, key);
    if (!(x > 0.0))
        throw StudyRowError(std::string("\"") + key + "\" = " + formatDouble(x) +
                            ": expected a number > 0");
    return x;
}

std::optional<double> optionalPositive(const nlohmann::json& j, const char* key) {
    if (!j.contains(key) || j[key].is_null()) return std::nullopt;
    return positive(j, key);
}

// Two optional positive numbers that come together or not at all.
std::pair<std::optional<double>, std::optional<double>>
optionalPositivePair(const nlohmann::json& j, const char* first, const char* second) {
    auto pair = std::pair(optionalPositive(j, first), optionalPositive(j, second));
    if (pair.first.has_value() != pair.second.has_value())
        throw StudyRowError(std::string("\"") + first + "\" and \"" + second +
                            "\": one without the other");
    return pair;
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

void addStudySetJson(ojson& j, const StudyRow& r) {
    if (r.block) {
        j["block"] = studyBlockJson(*r.block);
    } else {
        j["mu"] = r.mu;
        j["tstar"] = r.tstar;
        j["limit"] = r.limit;
    }
    j["floor_period_s"] = orNull<ojson>(r.floorPeriod);
    j["floor_damping"] = orNull<ojson>(r.floorDamping);
    if (r.level) j["level"] = *r.level;
    if (r.motion) j["motion"] = *r.motion;
}

// nlohmann's dump writes the shortest text that reads back as the same double, in the C
// locale's syntax whatever the process locale: the same bytes on every machine and rerun.
std::string studyRowLine(const StudyRow& r) {
    ojson j = {{"case", r.index},
               {"cases", r.cases},
               {"study", r.study},
               {"set", r.set},
               {"record", r.record}};
    addStudySetJson(j, r);
    if (r.polarity) j["polarity"] = *r.polarity;
    j["measure"] = r.measure;
    j["record_im_g"] = r.recordIntensity;
    if (r.scale) {
        j["scale"] = *r.scale;
        j["im_as_given_g"] = r.imAsGiven;
    }
    j["critical_im_g"] = orNull<ojson>(r.criticalIntensity);
    j["critical_peak_g"] = orNull<ojson>(r.criticalPeak);
    j["limit_im_g"] = r.limitIntensity;
    if (r.scale) {
        j["collapses_as_given"] = r.collapsesAsGiven;
        j["margin"] = orNull<ojson>(r.margin);
    }
    if (!r.noFit.empty()) j["no_fit"] = r.noFit;
    j["runs"] = r.runs;
    if (r.runLimitReached) j["run_limit_reached"] = true;
    return j.dump();
}

std::string studyRowsText(const std::vector<StudyRow>& rows) {
    std::string text;
    for (const StudyRow& r : rows)
        text += studyRowLine(r) + "\n";
    return text;
}

namespace {

// The case's inputs: what the study file says about it.
void parseInputs(const nlohmann::json& j, StudyRow& r) {
    r.index = count(j, "case");
    r.cases = count(j, "cases");
    if (r.index >= r.cases) throw StudyRowError("\"case\": not below \"cases\"");
    r.study = text(j, "study");
    if (!isStudyFingerprint(r.study))
        throw StudyRowError("\"study\" = " + quotedToken(r.study) +
                            ": expected the study's fingerprint (" +
                            std::to_string(kStudyFingerprintDigits) + " hex digits)");
    r.set = count(j, "set");
    if (r.set > r.index) throw StudyRowError("\"set\": above \"case\"");
    r.record = text(j, "record");
    if (r.record.empty()) throw StudyRowError("\"record\": empty");
    if (j.contains("block")) {
        try {
            r.block = studyBlockFromRowJson(j["block"]);
        } catch (const std::invalid_argument& e) {
            throw StudyRowError(e.what());
        }
    } else {
        r.mu = positive(j, "mu");
        r.tstar = positive(j, "tstar");
        r.limit = positive(j, "limit");
    }
    std::tie(r.floorPeriod, r.floorDamping) =
        optionalPositivePair(j, "floor_period_s", "floor_damping");
    r.measure = text(j, "measure");
    if (r.measure.empty()) throw StudyRowError("\"measure\": empty");
    if (j.contains("level")) {
        const std::size_t level = count(j, "level");
        if (level < 1 || level > 1000) throw StudyRowError("\"level\": expected 1 to 1000");
        r.level = static_cast<int>(level);
    }
    r.motion = optionalText(j, "motion");
    if (r.motion && r.motion != "record" && r.motion != "fitted_sine")
        throw StudyRowError("\"motion\" = " + quotedToken(*r.motion) +
                            ": expected \"record\" or \"fitted_sine\"");
    r.polarity = optionalText(j, "polarity");
    if (r.polarity && r.polarity != "normal" && r.polarity != "inverted")
        throw StudyRowError("\"polarity\" = " + quotedToken(*r.polarity) +
                            ": expected \"normal\" or \"inverted\"");
}

// The case's result: intensities > 0, a critical one (with its peak) at most the search limit.
void parseResult(const nlohmann::json& j, StudyRow& r) {
    r.recordIntensity = positive(j, "record_im_g");
    std::tie(r.criticalIntensity, r.criticalPeak) =
        optionalPositivePair(j, "critical_im_g", "critical_peak_g");
    r.limitIntensity = positive(j, "limit_im_g");
    if (r.criticalIntensity && *r.criticalIntensity > r.limitIntensity)
        throw StudyRowError("\"critical_im_g\" = " + formatDouble(*r.criticalIntensity) +
                            ": above \"limit_im_g\" = " + formatDouble(r.limitIntensity));
    r.runs = static_cast<long>(count(j, "runs"));
    if (j.contains("run_limit_reached")) {
        if (!j["run_limit_reached"].is_boolean())
            throw StudyRowError("\"run_limit_reached\": expected true or false");
        r.runLimitReached = j["run_limit_reached"].get<bool>();
    }
    r.noFit = optionalText(j, "no_fit").value_or("");
    r.scale = optionalPositive(j, "scale");
    if (!r.scale) return;
    r.imAsGiven = positive(j, "im_as_given_g");
    if (!j.contains("collapses_as_given") || !j["collapses_as_given"].is_boolean())
        throw StudyRowError("\"collapses_as_given\": expected true or false");
    r.collapsesAsGiven = j["collapses_as_given"].get<bool>();
    r.margin = optionalPositive(j, "margin");
}

} // namespace

StudyRow parseStudyRow(const std::string& line) {
    const nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
    if (j.is_discarded() || !j.is_object()) throw StudyRowError("not a JSON object");
    StudyRow r;
    parseInputs(j, r);
    parseResult(j, r);
    return r;
}

} // namespace kinstab
