// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/records/CsmipV2Reader.h"

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"

#include <regex>

namespace kinstab {

namespace {

bool startsChannel(const std::string& line) {
    return lowerCase(line).rfind("corrected accelerogram", 0) == 0;
}

const CsmipChannel& pick(const RecordText& text, const std::vector<CsmipChannel>& channels,
                         const std::string& wanted) {
    if (wanted.empty()) return channels.front();
    for (const CsmipChannel& c : channels)
        if (std::to_string(c.number) == trimmed(wanted) ||
            lowerCase(c.name) == lowerCase(trimmed(wanted)))
            return c;
    std::string list;
    for (const CsmipChannel& c : channels)
        list += (list.empty() ? "" : ", ") + std::to_string(c.number) + " " + c.name;
    text.failFile("channel " + quotedToken(wanted) +
                  " is not in the file; it has: " + elided(list, 400));
}

void describe(Accelerogram& a, const RecordText& text, const CsmipChannel& c, std::size_t end) {
    a.component = "CHAN " + std::to_string(c.number) + ": " + c.name;
    if (c.firstLine + 6 < end) {
        a.name = trimmed(text.line(c.firstLine + 2));
        const std::string station = text.line(c.firstLine + 6);
        a.station = trimmed(station.substr(0, station.find("   "))); // text before the next column
    }
}

// "PEAK ACCELERATION =   429.355    CM/SEC/SEC  AT    3.960   SEC."
std::optional<double> headerPeak(const RecordText& text, std::size_t from, std::size_t to) {
    static const std::regex re(R"(peak\s+acceleration\s*=\s*(\S+)\s+(\S+))", std::regex::icase);
    for (std::size_t i = from; i < to; ++i) {
        std::smatch m;
        const std::string l = text.header(i);
        if (!std::regex_search(l, m, re)) continue;
        const auto value = parseNumber(m[1].str());
        const auto unit = accelUnitFromName(m[2].str());
        if (value && unit) return *value * gPerUnit(*unit);
    }
    return std::nullopt;
}

} // namespace

std::vector<CsmipChannel> csmipChannels(const RecordText& text) {
    static const std::regex chan(R"(chan\s*(\d+)\s*:\s*(\S+))", std::regex::icase);
    std::vector<CsmipChannel> out;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (!startsChannel(text.line(i))) continue;
        std::smatch m;
        const std::string l = text.header(i);
        if (!std::regex_search(l, m, chan)) text.fail(i, "channel header without 'CHAN n: NAME'");
        const auto number = parseCount(m[1].str(), 1'000'000);
        if (!number) text.fail(i, "channel number " + quotedToken(m[1].str()) + " is too large");
        out.push_back({static_cast<int>(*number), m[2].str(), i});
    }
    return out;
}

Accelerogram parseCsmipV2(const RecordText& text, const std::string& channel) {
    if (text.skipBlank(0) == text.size()) text.failFile("empty file: no CSMIP V2 header");
    if (!startsChannel(text.line(text.skipBlank(0))))
        text.fail(text.skipBlank(0),
                  "not a CSMIP V2 file: expected 'CORRECTED ACCELEROGRAM' on the first line");
    const std::vector<CsmipChannel> channels = csmipChannels(text);
    const CsmipChannel& c = pick(text, channels, channel);
    std::size_t end = text.size();
    for (const CsmipChannel& other : channels)
        if (other.firstLine > c.firstLine) end = std::min(end, other.firstLine);

    static const std::regex block(
        R"(^\s*(\d+)\s+points of accel data equally spaced at\s+(\S+)\s+sec)", std::regex::icase);
    static const std::regex units(R"((?:units:\s*|\bin\s+)([a-z/0-9]+))", std::regex::icase);
    for (std::size_t i = c.firstLine; i < end; ++i) {
        std::smatch m;
        const std::string l = text.header(i);
        if (!std::regex_search(l, m, block)) continue;
        Accelerogram a;
        a.sourceFile = text.source();
        a.format = "CSMIP V2";
        const auto npts = parseCount(m[1].str(), limits::kMaxRecordSamples);
        if (!npts || *npts < 2)
            text.fail(i, "number of points " + quotedToken(m[1].str()) + " must be 2 to " +
                             std::to_string(limits::kMaxRecordSamples));
        a.dt = finiteAt(text, i, m[2].str(), "sample interval");
        if (a.dt <= 0.0)
            text.fail(i, "sample interval " + quotedToken(m[2].str()) + " must be > 0");
        const std::string rest = m.suffix().str();
        std::smatch u;
        if (!std::regex_search(rest, u, units)) text.fail(i, "no units on the data line");
        const std::string unitName = trimmed(u[1].str());
        const auto unit = accelUnitFromName(
            unitName.back() == '.' ? unitName.substr(0, unitName.size() - 1) : unitName);
        if (!unit) text.fail(i, "unknown units " + quotedToken(unitName));
        a.fileUnit = *unit;
        const FixedFormat format =
            parseFortranFormat(rest).value_or(FixedFormat{8, 10}); // old files: 8F10.3
        std::size_t next = 0;
        a.samples = readFixedValues(text, i + 1, *npts, format, next);
        for (double& x : a.samples)
            x *= gPerUnit(a.fileUnit);
        a.headerPeak = headerPeak(text, c.firstLine, i);
        describe(a, text, c, end);
        return a;
    }
    text.fail(end - 1,
              "channel " + std::to_string(c.number) + " has no 'POINTS OF ACCEL DATA' block");
}

Accelerogram readCsmipV2(const std::string& path, const std::string& channel) {
    return parseCsmipV2(RecordText::fromFile(path), channel);
}

} // namespace kinstab
