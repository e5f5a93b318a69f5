// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/records/At2Reader.h"

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"

#include <cmath>
#include <regex>

namespace kinstab {

namespace {

constexpr std::size_t kMaxHeaderLines = 10;

struct NptsLine {
    std::size_t line = 0;
    std::string npts, dt; // tokens as written
};

std::optional<NptsLine> findNptsLine(const RecordText& text) {
    static const std::regex labelled(R"(NPTS\s*=\s*([^,\s]*)\s*,?\s*DT\s*=\s*([^\s,]*))",
                                     std::regex::icase);
    static const std::regex valuesFirst(R"(^\s*(\S+)\s+(\S+)\s+NPTS\s*,?\s*DT)", std::regex::icase);
    for (std::size_t i = 0; i < std::min(text.size(), kMaxHeaderLines); ++i) {
        std::smatch m;
        const std::string l = text.header(i);
        if (std::regex_search(l, m, labelled) || std::regex_search(l, m, valuesFirst))
            return NptsLine{i, m[1].str(), m[2].str()};
    }
    return std::nullopt;
}

// "ACCELERATION TIME SERIES IN UNITS OF G", "The units are (g)"; g when nothing is said.
AccelUnit headerUnit(const RecordText& text, std::size_t nptsLine) {
    for (std::size_t i = 0; i < nptsLine; ++i) {
        const std::string l = lowerCase(text.header(i));
        const std::size_t at = l.find("units");
        if (at == std::string::npos) continue;
        const std::string rest = l.substr(at);
        if (rest.find("cm/s") != std::string::npos || rest.find("gal") != std::string::npos)
            return AccelUnit::CmPerS2;
        if (rest.find("in/s") != std::string::npos) return AccelUnit::InPerS2;
        if (rest.find("ft/s") != std::string::npos) return AccelUnit::FtPerS2;
        if (rest.find("m/s") != std::string::npos) return AccelUnit::MetresPerS2;
        if (std::regex_search(rest, std::regex(R"((of|\()\s*g\b)"))) return AccelUnit::G;
        text.fail(i, "unknown units in " + quotedToken(text.line(i)));
    }
    return AccelUnit::G;
}

// Line 2: "San Fernando, 2/9/1971, Pacoima Dam (upper left abut), 164": station is the
// next-to-last comma field, component the last.
void describe(Accelerogram& a, const RecordText& text) {
    if (text.size() < 2) return;
    a.name = trimmed(text.line(1));
    std::vector<std::string> fields;
    std::size_t start = 0;
    const std::string& l = text.line(1);
    while (true) {
        const std::size_t comma = l.find(',', start);
        fields.push_back(trimmed(l.substr(start, comma - start)));
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    if (fields.size() >= 3) {
        a.station = fields[fields.size() - 2];
        a.component = fields.back();
    }
}

} // namespace

Accelerogram parseAt2(const RecordText& text) {
    if (text.skipBlank(0) == text.size()) text.failFile("empty file: no AT2 header");
    const std::optional<NptsLine> h = findNptsLine(text);
    if (!h)
        text.fail(std::min(text.size(), kMaxHeaderLines) - 1,
                  "no 'NPTS=..., DT=...' line in the first " + std::to_string(kMaxHeaderLines) +
                      " lines");
    const double npts = finiteAt(text, h->line, h->npts, "NPTS");
    if (npts < 2 || npts != std::floor(npts) ||
        npts > static_cast<double>(limits::kMaxRecordSamples))
        text.fail(h->line, "NPTS " + quotedToken(h->npts) + " must be a whole number from 2 to " +
                               std::to_string(limits::kMaxRecordSamples));
    Accelerogram a;
    a.sourceFile = text.source();
    a.format = "PEER AT2";
    a.dt = finiteAt(text, h->line, h->dt, "DT");
    if (a.dt <= 0.0) text.fail(h->line, "DT " + quotedToken(h->dt) + " must be > 0");
    a.fileUnit = headerUnit(text, h->line);
    describe(a, text);
    a.samples = readFreeValues(text, h->line + 1);
    const auto n = static_cast<std::size_t>(npts);
    if (a.samples.size() != n) {
        const std::size_t last = text.size() == 0 ? 0 : text.size() - 1;
        text.fail(a.samples.size() < n ? last : h->line,
                  "NPTS on line " + std::to_string(h->line + 1) + " announces " +
                      std::to_string(n) + " values, the file has " +
                      std::to_string(a.samples.size()) +
                      (a.samples.size() < n ? " (truncated?)" : ""));
    }
    for (double& x : a.samples)
        x *= gPerUnit(a.fileUnit);
    return a;
}

Accelerogram readAt2(const std::string& path) {
    return parseAt2(RecordText::fromFile(path));
}

} // namespace kinstab
