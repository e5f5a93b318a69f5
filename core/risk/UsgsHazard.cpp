// SPDX-License-Identifier: GPL-3.0-or-later
// The USGS hazard service's JSON (core/risk/HazardFile.h), as its web service writes it:
//   {"response": [{"metadata": {"imt": {"value": "PGA", ...}, "xvalues": [0.005, ...], ...},
//                  "data": [{"component": "Total", "yvalues": [...]}, ...]}, ...]}
// One response per intensity measure; data[0] is the total curve.

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"
#include "core/io/JsonReader.h"
#include "core/risk/HazardReaders.h"

#include <cmath>

namespace kinstab {

namespace {

using json = nlohmann::json;

const json& member(const json& j, const char* key, const std::string& path,
                   const std::string& label) {
    if (!j.is_object() || !j.contains(key))
        throw HazardError(label + ": " + path + ": missing (expected \"" + key + "\")");
    return j[key];
}

std::vector<double> numbers(const json& j, const std::string& path, const std::string& label) {
    if (!j.is_array()) throw HazardError(label + ": " + path + ": expected an array of numbers");
    if (j.size() > limits::kMaxHazardPoints)
        throw HazardError(label + ": " + path + ": " + std::to_string(j.size()) +
                          " values, more than the limit of " +
                          std::to_string(limits::kMaxHazardPoints));
    std::vector<double> v;
    for (std::size_t i = 0; i < j.size(); ++i) {
        if (!j[i].is_number())
            throw HazardError(label + ": " + path + "[" + std::to_string(i) + "]: " + j[i].dump() +
                              " is not a number");
        v.push_back(j[i].get<double>());
    }
    return v;
}

std::string imtOf(const json& response, const std::string& path, const std::string& label) {
    const std::string at = path + ".metadata.imt.value";
    const json& imt =
        member(member(member(response, "metadata", path, label), "imt", path + ".metadata", label),
               "value", path + ".metadata.imt", label);
    if (!imt.is_string()) throw HazardError(label + ": " + at + ": expected a string");
    return imt.get<std::string>();
}

HazardCurve curveOf(const json& response, const HazardMeasure& measure, const std::string& path,
                    const std::string& label) {
    const std::string xPath = path + ".metadata.xvalues", yPath = path + ".data[0].yvalues";
    const std::vector<double> x = numbers(
        member(member(response, "metadata", path, label), "xvalues", path + ".metadata", label),
        xPath, label);
    const json& data = member(response, "data", path, label);
    if (!data.is_array() || data.empty())
        throw HazardError(label + ": " + path + ".data: expected a non-empty array");
    const std::vector<double> y =
        numbers(member(data[0], "yvalues", path + ".data[0]", label), yPath, label);
    if (x.size() != y.size())
        throw HazardError(label + ": " + yPath + ": " + std::to_string(y.size()) +
                          " values for the " + std::to_string(x.size()) + " of " + xPath);
    std::vector<HazardPoint> points;
    for (std::size_t i = 0; i < x.size(); ++i)
        points.push_back({x[i], y[i]});
    return hazardCurve(measure, std::move(points),
                       label + ", " + path + " (" + hazardMeasureName(measure) + ")",
                       [&](std::size_t i) {
                           const std::string k = "[" + std::to_string(i) + "]";
                           return label + ": " + xPath + k + ", " + yPath + k;
                       });
}

} // namespace

HazardCurve parseUsgsHazard(const std::string& text, const std::string& label,
                            const HazardRequest& request) {
    json doc;
    try {
        doc = parseJsonDocument(text, limits::kMaxHazardFileBytes);
    } catch (const JsonFieldError& e) {
        throw HazardError(label + ": " + e.what());
    }
    const json& responses = member(doc, "response", "(top level)", label);
    if (!responses.is_array() || responses.empty())
        throw HazardError(label + ": response: expected a non-empty array");
    std::string held; // the measures of the file, for a message
    for (std::size_t i = 0; i < responses.size(); ++i) {
        const std::string path = "response[" + std::to_string(i) + "]";
        const std::string imt = imtOf(responses[i], path, label);
        const std::optional<HazardMeasure> m = measureFromUsgs(imt);
        if (!m && responses.size() == 1)
            throw HazardError(label + ": " + path + ".metadata.imt.value: unknown intensity " +
                              "measure " + quotedToken(imt) +
                              " (kinstab's fragilities are in g: PGA or SA0P2-style Sa)");
        if (i < 10) // a message names the first ten
            held += (held.empty() ? "" : ", ") + quotedToken(imt) + (m ? "" : " (unknown)");
        else if (i == 10)
            held += ", ...";
        if (m && (request.measure ? sameMeasure(*m, *request.measure) : responses.size() == 1))
            return curveOf(responses[i], *m, path, label);
    }
    if (!request.measure)
        throw HazardError(label + ": " + std::to_string(responses.size()) +
                          " intensity measures (" + held + "): name the one to use");
    throw HazardError(label + ": the hazard file has no curve for the fragility's intensity " +
                      "measure " + hazardMeasureName(*request.measure) + " (it holds " + held +
                      ")");
}

} // namespace kinstab
