#include "core/io/RecordReader.h"

#include "core/io/At2Reader.h"
#include "core/io/CosmosReader.h"
#include "core/io/CsmipV2Reader.h"
#include "core/io/PlainTextReader.h"

#include <algorithm>

namespace kinstab {

namespace {
const std::pair<RecordFormat, const char*> kNames[] = {
    {RecordFormat::Auto, "auto"},     {RecordFormat::At2, "at2"},
    {RecordFormat::Cosmos, "cosmos"}, {RecordFormat::CsmipV2, "csmip"},
    {RecordFormat::Values, "values"}, {RecordFormat::TimeAccel, "time-accel"},
};
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
    Accelerogram a;
    switch (detectRecordFormat(text, options)) {
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
    return a;
}

Accelerogram readRecord(const std::string& path, const RecordReadOptions& options) {
    return parseRecord(RecordText::fromFile(path), options);
}

} // namespace kinstab
