// SPDX-License-Identifier: GPL-3.0-or-later
// The plain hazard CSV (core/risk/HazardFile.h): "im_g,annual_rate" and a row per point; blank
// lines and '#' comments skipped, "# imt=..." states the measure.

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"
#include "core/friction/TripletCsv.h"
#include "core/risk/HazardReaders.h"

namespace kinstab {

namespace {

// "# imt=PGA" or "# imt = SA(1.0)": the measure; none for any other comment.
std::optional<std::string> imtComment(const std::string& line) {
    const std::string body = trimmed(std::string_view(line).substr(1));
    if (body.rfind("imt", 0) != 0) return std::nullopt;
    const std::string rest = trimmed(std::string_view(body).substr(3));
    if (rest.empty() || rest.front() != '=') return std::nullopt;
    return trimmed(std::string_view(rest).substr(1));
}

std::vector<std::string> fields(const std::string& line, const std::string& where) {
    try {
        return splitCsvLine(line);
    } catch (const std::invalid_argument& e) {
        throw HazardError(where + ": " + e.what());
    }
}

} // namespace

HazardCurve parseCsvHazard(std::string_view text, const std::string& label,
                           const HazardRequest& request) {
    HazardMeasure measure;
    std::size_t measureLine = 0;
    bool header = false;
    std::vector<HazardPoint> points;
    std::vector<std::size_t> pointLines; // of each point, for messages
    TextLines cursor(text);
    for (std::string_view raw; cursor.next(raw);) {
        const std::size_t line = cursor.number();
        const std::string row = trimmed(raw);
        const std::string where = hazardLine(label, line);
        if (row.empty()) continue;
        if (row.front() == '#') {
            if (const auto imt = imtComment(row)) {
                const auto m = measureFromOpenQuake(*imt);
                if (!m)
                    throw HazardError(where + ": unknown intensity measure " + quotedToken(*imt) +
                                      " (PGA or SA(T), T in s)");
                measure = *m, measureLine = line;
            }
        } else if (!header) {
            const std::vector<std::string> f = fields(row, where);
            if (f.size() != 2 || trimmed(f[0]) != "im_g" || trimmed(f[1]) != "annual_rate")
                throw HazardError(where + ": the header must be im_g,annual_rate, got " +
                                  quotedToken(row));
            header = true;
        } else {
            const std::vector<std::string> f = fields(row, where);
            if (f.size() != 2)
                throw HazardError(where + ": " + std::to_string(f.size()) +
                                  " fields, expected 2 (im_g,annual_rate)");
            if (points.size() == limits::kMaxHazardPoints)
                throw HazardError(where + ": more than the limit of " +
                                  std::to_string(limits::kMaxHazardPoints) + " points");
            points.push_back(
                {hazardNumber(f[0], where, "im_g"), hazardNumber(f[1], where, "annual_rate")});
            pointLines.push_back(line);
        }
    }
    if (!header) throw HazardError(label + ": no header line im_g,annual_rate");
    checkHazardMeasure(measure, request, hazardLine(label, measureLine));
    return hazardCurve(measure, std::move(points), label,
                       [&](std::size_t i) { return hazardLine(label, pointLines[i]); });
}

} // namespace kinstab
