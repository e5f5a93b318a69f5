// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/records/CosmosReader.h"

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"

#include <cmath>
#include <regex>

namespace kinstab {

namespace {

constexpr double kUnknown = -999.0; // COSMOS "value unknown"

// A count written in a header: whole, and no more than the lines or samples a file may have.
std::size_t countAt(const RecordText& text, std::size_t i, const std::string& token,
                    const char* what) {
    const auto n = parseCount(token, limits::kMaxRecordSamples);
    if (!n)
        text.fail(i, std::string(what) + " " + quotedToken(token) +
                         ": expected a whole number within the limit of " +
                         std::to_string(limits::kMaxRecordSamples));
    return *n;
}

// "100 Integer-header values follow on 10 lines, Format= (10I8)": count and line count.
std::pair<std::size_t, std::size_t> blockSize(const RecordText& text, std::size_t i,
                                              const char* what) {
    static const std::regex re(R"(^\s*(\d+)\s+\S*header values follow on\s+(\d+)\s+lines)",
                               std::regex::icase);
    std::smatch m;
    if (i >= text.size())
        text.fail(text.size() - 1, std::string("file ends before the ") + what + " header block");
    const std::string l = text.header(i);
    if (!std::regex_search(l, m, re))
        text.fail(i, std::string("expected the ") + what +
                         " header line '... values follow on ... lines'");
    return {countAt(text, i, m[1].str(), "header value count"),
            countAt(text, i, m[2].str(), "header line count")};
}

std::vector<double> realHeader(const RecordText& text, std::size_t& i) {
    const auto [count, lines] = blockSize(text, i, "real");
    const auto format = parseFortranFormat(text.line(i)).value_or(FixedFormat{5, 15});
    std::size_t next = 0;
    std::vector<double> values = readFixedValues(text, i + 1, count, format, next);
    if (next != i + 1 + lines)
        text.fail(i, "real header block does not span the lines it announces");
    i = next;
    return values;
}

void describe(Accelerogram& a, const RecordText& text, std::size_t textLines) {
    static const std::regex chan(R"(Chan\s+(\d+)\s*:\s*(.*?)\s*\(.*Location:\s*(.*))",
                                 std::regex::icase);
    a.name = trimmed(text.line(std::min<std::size_t>(1, textLines - 1)));
    for (std::size_t i = 0; i < textLines; ++i) {
        const std::string l = text.header(i);
        std::smatch m;
        if (l.rfind("Statn No:", 0) == 0)
            a.station = trimmed(l.substr(9));
        else if (std::regex_search(l, m, chan))
            a.component = "Chan " + m[1].str() + ": " + trimmed(m[2].str()) +
                          (trimmed(m[3].str()).empty() ? "" : ", " + trimmed(m[3].str()));
    }
}

// The first line's "(Format v01.20 with 13 text lines)": the text header's line count.
std::size_t textHeaderLines(const RecordText& text) {
    if (text.skipBlank(0) == text.size()) text.failFile("empty file: no COSMOS header");
    static const std::regex first(R"(\(Format\s+v\S*\s+with\s+(\d+)\s+text lines\))",
                                  std::regex::icase);
    std::smatch m;
    const std::string line0 = text.header(0);
    if (!std::regex_search(line0, m, first))
        text.fail(0, "not a COSMOS header: expected '(Format v01.20 with 13 text lines)'");
    const std::size_t textLines = countAt(text, 0, m[1].str(), "text line count");
    if (textLines < 1 || textLines + 3 > text.size())
        text.fail(0, "file ends inside the text header");
    return textLines;
}

// The line after the comment block that may start at line i ("N Comment line(s)").
std::size_t afterComments(const RecordText& text, std::size_t i) {
    static const std::regex comments(R"(^\s*(\d+)\s+Comment line)", std::regex::icase);
    std::smatch m;
    const std::string commentLine = i < text.size() ? text.header(i) : std::string();
    if (std::regex_search(commentLine, m, comments))
        i += 1 + countAt(text, i, m[1].str(), "comment line count");
    return i;
}

// "N acceleration pts, ..., units=..., Format=(...)": what the first data block holds.
struct DataHeader {
    std::size_t npts = 0;
    AccelUnit unit{};
    FixedFormat format{};
};

DataHeader dataHeader(const RecordText& text, std::size_t i) {
    static const std::regex data(R"(^\s*(\d+)\s+(\S+)\s+pts.*units\s*=\s*([^(,]*))",
                                 std::regex::icase);
    std::smatch m;
    if (i >= text.size()) text.fail(text.size() - 1, "file ends before the data header line");
    const std::string dataLine = text.header(i);
    if (!std::regex_search(dataLine, m, data))
        text.fail(i, "expected the data header 'N acceleration pts, ..., units=..., Format=(...)'");
    if (m[2].str().rfind("accel", 0) != 0)
        text.fail(i,
                  "the first data block holds " + quotedToken(m[2].str()) + ", not acceleration");
    const std::size_t npts = countAt(text, i, m[1].str(), "number of points");
    const std::optional<AccelUnit> unit = accelUnitFromName(trimmed(m[3].str()));
    if (!unit) text.fail(i, "unknown units " + quotedToken(trimmed(m[3].str())));
    const std::size_t formatAt = lowerCase(text.line(i)).find("format");
    const std::optional<FixedFormat> format =
        formatAt == std::string::npos ? std::nullopt
                                      : parseFortranFormat(text.line(i).substr(formatAt));
    if (!format) text.fail(i, "no Fortran data format such as 'Format=(1E15.6)'");
    return {npts, *unit, *format};
}

// The samples after the data header at line i, in g; no more values than it announces.
std::vector<double> samples(const RecordText& text, std::size_t i, const DataHeader& h) {
    std::size_t next = 0;
    std::vector<double> values = readFixedValues(text, i + 1, h.npts, h.format, next);
    next = text.skipBlank(next);
    if (next < text.size() && parseNumber(splitWhitespace(text.line(next)).front()))
        text.fail(next,
                  "more values than the " + std::to_string(h.npts) + " the data header announces");
    for (double& x : values)
        x *= gPerUnit(h.unit);
    return values;
}

} // namespace

Accelerogram parseCosmos(const RecordText& text) {
    const std::size_t textLines = textHeaderLines(text);
    Accelerogram a;
    a.sourceFile = text.source();
    a.format = std::string("COSMOS ") +
               (text.line(0).find("Uncorrected") != std::string::npos ? "V1" : "V2");
    describe(a, text, textLines);

    std::size_t i = textLines;
    i += 1 + blockSize(text, i, "integer").second;
    const std::vector<double> real = realHeader(text, i);
    i = afterComments(text, i);
    const DataHeader header = dataHeader(text, i);
    if (real.size() < 64 || real[61] == kUnknown || !(real[61] > 0.0))
        text.fail(i, "sample interval (real header value 62, ms) is missing or unknown");
    a.dt = real[61] / 1000.0;
    a.fileUnit = header.unit;
    a.samples = samples(text, i, header);
    if (real[63] != kUnknown)
        a.headerPeak = real[63] * gPerUnit(a.fileUnit); // real #64: peak, data units
    return a;
}

Accelerogram readCosmos(const std::string& path) {
    return parseCosmos(RecordText::fromFile(path));
}

} // namespace kinstab
