// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/CodesJson.h"

#include "core/base/TextInput.h"
#include "core/io/JsonValue.h"

#include "core/io/ResultJson.h"

#include <algorithm>

namespace kinstab {

using nlohmann::json;

namespace {

template <class T> void putOptional(json& j, const char* key, const std::optional<T>& v) {
    j[key] = orNull(v);
}

std::string choices(const std::vector<std::string>& names) {
    std::string s;
    for (const auto& n : names)
        s += (s.empty() ? "" : "|") + n;
    return s;
}

template <class E, class F>
E enumField(const JsonReader& r, const std::string& key, E fallback, F fromName,
            const std::string& allowed) {
    const auto t = r.optionalText(key);
    if (!t) return fallback;
    const auto v = fromName(*t);
    if (!v) r.fail(key, quotedToken(*t) + " must be one of " + allowed);
    return *v;
}

} // namespace

json buildingToJson(const Building& b) {
    json j = {{"name", b.name},
              {"stories", b.stories},
              {"unit", unitName(b.unit)},
              {"height", b.height},
              {"plan_dimension", b.planDimension},
              {"system", systemName(b.system)},
              {"occupancy", occupancyName(b.occupancy)},
              {"story_weights", b.storyWeights},
              {"story_heights", b.storyHeights}};
    putOptional(j, "period_s", b.period);
    return j;
}

Building buildingFromJson(const JsonReader& r) {
    Building b;
    b.name = r.text("name", "");
    b.stories = r.integer("stories", b.stories);
    b.unit = enumField(r, "unit", b.unit, unitFromName, "ft|m");
    b.height = r.requiredNumber("height");
    b.planDimension = r.requiredNumber("plan_dimension");
    b.period = r.optionalNumber("period_s");
    b.system = enumField(r, "system", b.system, systemFromName, choices(systemNames()));
    b.occupancy =
        enumField(r, "occupancy", b.occupancy, occupancyFromName, choices(occupancyNames()));
    if (r.has("story_weights")) b.storyWeights = r.numbers("story_weights");
    if (r.has("story_heights")) b.storyHeights = r.numbers("story_heights");
    requireValidBuilding(b);
    return b;
}

namespace {

json ubc1976Json(const Ubc1976Inputs& in) {
    json j = {{"zone", in.zone}, {"k", in.k}};
    putOptional(j, "importance", in.importance);
    putOptional(j, "site_period_s", in.sitePeriod);
    return j;
}

Ubc1976Inputs ubc1976From(const JsonReader& r) {
    Ubc1976Inputs in;
    in.zone = r.integer("zone", in.zone);
    in.importance = r.optionalNumber("importance");
    in.k = r.requiredNumber("k");
    in.sitePeriod = r.optionalNumber("site_period_s");
    return in;
}

json atcJson(const Atc306Inputs& in) {
    json j = {{"aa", in.aa}, {"av", in.av}, {"soil", atcSoilName(in.soil)}, {"r", in.r}};
    putOptional(j, "map_area", in.mapArea);
    return j;
}

Atc306Inputs atcFrom(const JsonReader& r) {
    Atc306Inputs in;
    in.mapArea = r.optionalInteger("map_area");
    if (!in.mapArea) {
        in.aa = r.requiredNumber("aa");
        in.av = r.requiredNumber("av");
    } else {
        in.aa = in.av = atcMapAreaCoefficient(std::clamp(*in.mapArea, 1, 7));
    }
    in.soil = enumField(r, "soil", in.soil, atcSoilFromName, "S1|S2|S3");
    in.r = r.requiredNumber("r");
    return in;
}

json ubc1997Json(const Ubc1997Inputs& in) {
    json j = {{"zone", ubc97ZoneName(in.zone)},
              {"soil", ubc97SoilName(in.soil)},
              {"na", in.na},
              {"nv", in.nv},
              {"r", in.r}};
    putOptional(j, "importance", in.importance);
    return j;
}

Ubc1997Inputs ubc1997From(const JsonReader& r) {
    Ubc1997Inputs in;
    in.zone = enumField(r, "zone", in.zone, ubc97ZoneFromName, "1|2A|2B|3|4");
    in.soil = enumField(r, "soil", in.soil, ubc97SoilFromName, "SA|SB|SC|SD|SE");
    in.na = r.number("na", 1.0);
    in.nv = r.number("nv", 1.0);
    in.importance = r.optionalNumber("importance");
    in.r = r.requiredNumber("r");
    return in;
}

json asceJson(const Asce7Inputs& in) {
    json j = {
        {"sds", in.sds}, {"sd1", in.sd1}, {"tl", in.tl}, {"site_class", in.siteClass}, {"r", in.r}};
    putOptional(j, "s1", in.s1);
    putOptional(j, "risk_category", in.riskCategory);
    putOptional(j, "importance", in.importance);
    return j;
}

Asce7Inputs asceFrom(const JsonReader& r) {
    Asce7Inputs in;
    in.sds = r.requiredNumber("sds");
    in.sd1 = r.requiredNumber("sd1");
    in.s1 = r.optionalNumber("s1");
    in.tl = r.requiredNumber("tl");
    in.siteClass = r.text("site_class", in.siteClass);
    in.riskCategory = r.optionalInteger("risk_category");
    in.importance = r.optionalNumber("importance");
    in.r = r.requiredNumber("r");
    return in;
}

json ec8Json(const Eurocode8Inputs& in) {
    json j = {{"ground", ec8GroundName(in.ground)},
              {"spectrum_type", in.spectrumType},
              {"agr", in.agr},
              {"q", in.q},
              {"beta", in.beta},
              {"regular_in_elevation", in.regularInElevation}};
    putOptional(j, "importance_class", in.importanceClass);
    putOptional(j, "gamma_i", in.gammaI);
    return j;
}

Eurocode8Inputs ec8From(const JsonReader& r) {
    Eurocode8Inputs in;
    in.ground = enumField(r, "ground", in.ground, ec8GroundFromName, "A|B|C|D|E");
    in.spectrumType = r.integer("spectrum_type", in.spectrumType);
    in.agr = r.requiredNumber("agr");
    in.importanceClass = r.optionalInteger("importance_class");
    in.gammaI = r.optionalNumber("gamma_i");
    in.q = r.requiredNumber("q");
    in.beta = r.number("beta", in.beta);
    in.regularInElevation = r.boolean("regular_in_elevation", true);
    return in;
}

} // namespace

json codesToJson(const CodeSelection& c) {
    json j = json::object();
    if (c.ubc1976) j["ubc1976"] = ubc1976Json(*c.ubc1976);
    if (c.atc306) j["atc306"] = atcJson(*c.atc306);
    if (c.ubc1997) j["ubc1997"] = ubc1997Json(*c.ubc1997);
    if (c.asce7_22) j["asce7_22"] = asceJson(*c.asce7_22);
    if (c.ec8) j["ec8"] = ec8Json(*c.ec8);
    return j;
}

CodeSelection codesFromJson(const JsonReader& r) {
    CodeSelection c;
    if (auto o = r.optionalObject("ubc1976")) c.ubc1976 = ubc1976From(*o);
    if (auto o = r.optionalObject("atc306")) c.atc306 = atcFrom(*o);
    if (auto o = r.optionalObject("ubc1997")) c.ubc1997 = ubc1997From(*o);
    if (auto o = r.optionalObject("asce7_22")) c.asce7_22 = asceFrom(*o);
    if (auto o = r.optionalObject("ec8")) c.ec8 = ec8From(*o);
    if (const std::string e = validateCodes(c); !e.empty()) throw InputError(e);
    return c;
}

json codeResultJson(const CodeResult& r) {
    json trail = json::array();
    for (const TrailEntry& t : r.trail)
        trail.push_back({{"name", t.name},
                         {"symbol", t.symbol},
                         {"value", numberOrNull(t.value)},
                         {"clause", t.clause}});
    json j = {{"title", r.title},
              {"base_shear_coefficient", r.baseShearCoefficient},
              {"period_s", r.periodSeconds},
              {"period_source", r.periodSource},
              {"top_ratio", r.topRatio},
              {"story_forces", r.storyForces},
              {"applicable", r.applicable},
              {"trail", trail},
              {"notes", r.notes}};
    if (r.topRatioWithoutFt) j["top_ratio_without_ft"] = *r.topRatioWithoutFt;
    return j;
}

json codeResultsJson(const std::vector<CodeResult>& results) {
    json j = json::object();
    for (const CodeResult& r : results)
        j[r.code] = codeResultJson(r);
    return j;
}

json designCheckJson(const DesignCheckResult& d) {
    json codes = json::object();
    for (const CodeVerdict& v : d.codes) {
        json c = {{"title", v.title},
                  {"ratio", v.ratio},
                  {"period_s", v.periodSeconds},
                  {"frequency_hz", v.frequencyHz},
                  {"a_crit", orNull(v.aCrit)},
                  {"margin", orNull(v.margin)},
                  {"verdict", verdictText(v.verdict)},
                  {"explanation", v.explanation}};
        if (v.ratioWithoutFt) c["ratio_without_ft"] = *v.ratioWithoutFt;
        codes[v.code] = c;
    }
    return {{"codes", codes}, {"runs", d.runs}};
}

} // namespace kinstab
