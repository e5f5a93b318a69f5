// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/risk/HazardFile.h"

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"
#include "core/io/StudyJson.h"
#include "core/risk/HazardReaders.h"

#include <algorithm>
#include <array>

namespace kinstab {

namespace {

// The project file's spelling (core/io/StudyJson.h), in the enum's order.
constexpr std::array<std::pair<HazardFormat, const char*>, 4> kFormatNames = {{
    {HazardFormat::Auto, kProjectHazardFormats[0]},
    {HazardFormat::OpenQuake, kProjectHazardFormats[1]},
    {HazardFormat::Usgs, kProjectHazardFormats[2]},
    {HazardFormat::Csv, kProjectHazardFormats[3]},
}};

} // namespace

std::string hazardFormatName(HazardFormat f) {
    for (const auto& [format, name] : kFormatNames)
        if (format == f) return name;
    return "auto";
}

std::optional<HazardFormat> hazardFormatFromName(const std::string& name) {
    for (const auto& [format, text] : kFormatNames)
        if (name == text) return format;
    return std::nullopt;
}

HazardFormat detectHazardFormat(const std::string& text) {
    const std::string_view body = trimmedView(withoutBom(text));
    if (!body.empty() && body.front() == '{') return HazardFormat::Usgs;
    const std::string_view first = body.substr(0, body.find('\n'));
    if (!first.empty() && first.front() == '#' &&
        first.find("investigation_time") != std::string_view::npos)
        return HazardFormat::OpenQuake;
    return HazardFormat::Csv;
}

HazardCurve parseHazardText(const std::string& text, const std::string& label,
                            const HazardRequest& request) {
    if (trimmedView(withoutBom(text)).empty()) throw HazardError(label + ": the file is empty");
    const HazardFormat format =
        request.format == HazardFormat::Auto ? detectHazardFormat(text) : request.format;
    // A USGS or CSV file holds one site: a site asked for would be silently ignored.
    if (request.site && format != HazardFormat::OpenQuake)
        throw HazardError(label + ": a site is given, but a " + hazardFormatName(format) +
                          " hazard file holds one site's curve");
    HazardCurve c =
        format == HazardFormat::OpenQuake ? parseOpenQuakeHazard(withoutBom(text), label, request)
        : format == HazardFormat::Usgs    ? parseUsgsHazard(text, label, request)
                                          : parseCsvHazard(withoutBom(text), label, request);
    c.format = hazardFormatName(format);
    return c;
}

HazardCurve readHazardFile(const std::string& path, const HazardRequest& request) {
    const FileText f = readTextFile(path, limits::kMaxHazardFileBytes);
    if (!f.error.empty()) throw HazardError(path + ": " + f.error);
    return parseHazardText(f.text, path, request);
}

bool TextLines::next(std::string_view& line) {
    if (pos_ >= text_.size()) return false;
    const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
    line = text_.substr(pos_, end - pos_);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    pos_ = end + 1; // strictly forward: the loop over lines ends
    ++number_;
    return true;
}

std::string hazardLine(const std::string& label, std::size_t line) {
    return label + ":" + std::to_string(line);
}

double hazardNumber(std::string_view field, const std::string& where, const std::string& column) {
    const std::string_view t = trimmedView(field);
    const std::optional<double> x = parseDouble(t);
    if (!x)
        throw HazardError(where + ", column '" + column + "': " + quotedToken(t) +
                          " is not a number");
    return *x;
}

void checkHazardMeasure(const HazardMeasure& stated, const HazardRequest& request,
                        const std::string& where) {
    if (!request.measure || stated.kind == HazardMeasure::Kind::Unstated) return;
    if (!sameMeasure(stated, *request.measure))
        throw HazardError(where + ": the hazard curve's intensity measure " +
                          hazardMeasureName(stated) + " is not the fragility's " +
                          hazardMeasureName(*request.measure));
}

} // namespace kinstab
