// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/records/RecordReader.h"

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"
#include "core/records/At2Reader.h"
#include "core/records/CosmosReader.h"
#include "core/records/CsmipV2Reader.h"
#include "core/records/PlainTextReader.h"

#include <algorithm>
#include <cmath>

namespace kinstab {

namespace {
const std::pair<RecordFormat, const char*> kNames[] = {
    {RecordFormat::Auto, "auto"},     {RecordFormat::At2, "at2"},
    {RecordFormat::Cosmos, "cosmos"}, {RecordFormat::CsmipV2, "csmip"},
    {RecordFormat::Values, "values"}, {RecordFormat::TimeAccel, "time-accel"},
};

// What a file's numbers may be (core/base/InputLimits.h), and header text short enough to show.
void checkLimits(const RecordText& text, Accelerogram& a) {
    using namespace limits;
    if (std::isfinite(a.dt) && (a.dt < kMinRecordDt || a.dt > kMaxRecordDt))
        text.failFile("sample interval " + formatDouble(a.dt) + " s is outside " +
                      formatDouble(kMinRecordDt) + " to " + formatDouble(kMaxRecordDt) + " s");
    if (a.samples.size() > kMaxRecordSamples)
        text.failFile(std::to_string(a.samples.size()) + " samples: more than the limit of " +
                      std::to_string(kMaxRecordSamples));
    const SignedPeak p = a.peak();
    if (std::abs(p.value) > kMaxRecordAccelG)
        text.failFile("sample " + std::to_string(p.index + 1) + " is " + formatDouble(p.value) +
                      " g, beyond " + formatDouble(kMaxRecordAccelG) +
                      " g: are the units right (--record-unit, e.g. cm/s2)?");
    a.name = elided(a.name, kMaxNameChars);
    a.station = elided(a.station, kMaxNameChars);
    a.component = elided(a.component, kMaxNameChars);
}
} // namespace

std::string recordFormatName(RecordFormat f) {
    for (const auto& [format, name] : kNames)
        if (format == f) return name;
    return "auto";
}

std::optional<RecordFormat> recordFormatFromName(const std::string& name) {
    for (const auto& [format, n] : kNames)
        if (lowerCase(name) == n) return format;
    return std::nullopt;
}

RecordFormat detectRecordFormat(const RecordText& text, const RecordReadOptions& options) {
    if (options.format != RecordFormat::Auto) return options.format;
    const std::size_t first = text.skipBlank(0);
    if (first < text.size()) {
        const std::string l = lowerCase(text.line(first));
        if (l.find("(format v") != std::string::npos) return RecordFormat::Cosmos;
        if (l.rfind("corrected accelerogram", 0) == 0) return RecordFormat::CsmipV2;
    }
    for (std::size_t i = first; i < std::min(text.size(), first + 10); ++i)
        if (lowerCase(text.line(i)).find("npts") != std::string::npos) return RecordFormat::At2;
    return options.dt ? RecordFormat::Values : RecordFormat::TimeAccel;
}

Accelerogram parseRecord(const RecordText& text, const RecordReadOptions& options) {
    if (text.skipBlank(0) == text.size()) text.failFile("empty file");
    const AccelUnit unit = options.unit.value_or(AccelUnit::G);
    const RecordFormat format = detectRecordFormat(text, options);
    if (!trimmed(options.channel).empty() && format != RecordFormat::CsmipV2)
        text.failFile("channel " + quotedToken(options.channel) +
                      " was asked for, but only CSMIP V2 " +
                      "files have channels; this file reads as " + recordFormatName(format));
    Accelerogram a;
    switch (format) {
    case RecordFormat::At2:
        a = parseAt2(text);
        break;
    case RecordFormat::Cosmos:
        a = parseCosmos(text);
        break;
    case RecordFormat::CsmipV2:
        a = parseCsmipV2(text, options.channel);
        break;
    case RecordFormat::Values:
        if (!options.dt) text.failFile("a file of values only needs dt");
        a = parseValues(text, *options.dt, unit);
        break;
    case RecordFormat::Auto:
    case RecordFormat::TimeAccel:
        a = parseTimeAccel(text, unit);
        break;
    }
    validateAccelerogram(a);
    checkLimits(text, a);
    return a;
}

Accelerogram readRecord(const std::string& path, const RecordReadOptions& options) {
    return parseRecord(RecordText::fromFile(path), options);
}

} // namespace kinstab
