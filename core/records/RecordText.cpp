// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/records/RecordText.h"

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"

#include <algorithm>
#include <cmath>

namespace kinstab {

RecordText::RecordText(const std::string& whole, std::string source) : source_(std::move(source)) {
    const std::string_view text = withoutBom(whole);
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string_view line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        // Header text of old records is often Latin-1 ("M\xE9xico"): shown as UTF-8.
        lines_.push_back(utf8FromLegacy(line));
        start = end + 1;
    }
}

RecordText RecordText::fromFile(const std::string& path) {
    FileText f = readTextFile(path, limits::kMaxRecordFileBytes);
    if (!f.error.empty()) throw RecordError(path, 0, f.error);
    return RecordText(f.text, path);
}

bool RecordText::blank(std::size_t i) const {
    return lines_[i].find_first_not_of(" \t\f\v") == std::string::npos;
}

std::size_t RecordText::skipBlank(std::size_t i) const {
    while (i < size() && blank(i))
        ++i;
    return i;
}

void RecordText::fail(std::size_t i, const std::string& message) const {
    throw RecordError(source_, static_cast<int>(i + 1), message);
}

void RecordText::failFile(const std::string& message) const {
    throw RecordError(source_, 0, message);
}

std::optional<double> parseNumber(std::string_view token) {
    if (token.size() > 64) return std::nullopt; // no number in a record is that long
    std::string t(token);
    for (char& c : t)
        if (c == 'D' || c == 'd') c = 'E'; // Fortran double-precision exponent
    return parseDouble(t);
}

double finiteAt(const RecordText& text, std::size_t i, std::string_view token,
                const std::string& what) {
    const std::optional<double> x = parseNumber(token);
    if (!x) text.fail(i, what + " " + quotedToken(token) + " is not a number");
    if (!std::isfinite(*x))
        text.fail(i, what + " " + quotedToken(token) + " is not a finite number");
    return *x;
}

std::vector<std::string_view> splitWhitespace(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i])))
            ++i;
        std::size_t j = i;
        while (j < line.size() && !std::isspace(static_cast<unsigned char>(line[j])))
            ++j;
        if (j > i) out.push_back(line.substr(i, j - i));
        i = j;
    }
    return out;
}

std::string lowerCase(std::string s) {
    for (char& c : s)
        c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

std::vector<double> readFreeValues(const RecordText& text, std::size_t first) {
    std::vector<double> values;
    for (std::size_t i = first; i < text.size(); ++i)
        for (std::string_view token : splitWhitespace(text.line(i))) {
            if (values.size() == limits::kMaxRecordSamples)
                text.fail(i, "more than the limit of " + std::to_string(limits::kMaxRecordSamples) +
                                 " samples");
            values.push_back(
                finiteAt(text, i, token, "value " + std::to_string(values.size() + 1)));
        }
    return values;
}

std::optional<FixedFormat> parseFortranFormat(std::string_view spec) {
    // "(8f10.6)", "(1E15.6)", "Format=(1E15.6)": count, letter E/F, width.
    // Counts and widths beyond 3 digits are refused before they could overflow an int.
    const std::size_t open = spec.find('(');
    if (open == std::string_view::npos) return std::nullopt;
    std::size_t i = open + 1;
    int count = 0;
    while (i < spec.size() && std::isdigit(static_cast<unsigned char>(spec[i]))) {
        count = count * 10 + (spec[i++] - '0');
        if (count > 999) return std::nullopt;
    }
    if (i >= spec.size() || (std::toupper(static_cast<unsigned char>(spec[i])) != 'E' &&
                             std::toupper(static_cast<unsigned char>(spec[i])) != 'F'))
        return std::nullopt;
    ++i;
    int width = 0;
    while (i < spec.size() && std::isdigit(static_cast<unsigned char>(spec[i]))) {
        width = width * 10 + (spec[i++] - '0');
        if (width > 999) return std::nullopt;
    }
    if (width <= 0 || width > 64) return std::nullopt;
    return FixedFormat{count > 0 ? count : 1, width};
}

namespace {
// A line that closes a data block or opens the next one: the block ended early.
bool isBlockBoundary(const std::string& line) {
    std::string lower;
    for (char c : line)
        lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    const std::size_t first = lower.find_first_not_of(" \t");
    return (first != std::string::npos && lower.compare(first, 2, "/&") == 0) ||
           lower.find("points of") != std::string::npos ||
           lower.find("end of data") != std::string::npos ||
           lower.find("end-of-data") != std::string::npos ||
           lower.find(" pts") != std::string::npos;
}
} // namespace

std::vector<double> readFixedValues(const RecordText& text, std::size_t first, std::size_t n,
                                    FixedFormat format, std::size_t& next) {
    // A count announced by a header is checked before anything is reserved, and at most what
    // the lines that follow can hold is reserved: a header claiming 4e18 values allocates none.
    if (n > limits::kMaxRecordSamples)
        text.fail(first == 0 ? 0 : first - 1,
                  "the header announces " + std::to_string(n) + " values, more than the limit of " +
                      std::to_string(limits::kMaxRecordSamples) + " samples");
    const std::size_t lines = first < text.size() ? text.size() - first : 0;
    std::vector<double> values;
    values.reserve(std::min(n, lines * static_cast<std::size_t>(format.perLine)));
    std::size_t i = first;
    const auto w = static_cast<std::size_t>(format.width);
    for (; i < text.size() && values.size() < n; ++i) {
        const std::string& line = text.line(i);
        if (isBlockBoundary(line)) break;
        for (int k = 0; k < format.perLine && values.size() < n; ++k) {
            const std::size_t at = static_cast<std::size_t>(k) * w;
            if (at >= line.size()) break;
            const std::string field = line.substr(at, w);
            const auto tokens = splitWhitespace(field);
            if (tokens.empty()) {
                if (line.find_first_not_of(" \t", at) == std::string::npos)
                    break; // padded short line
                text.fail(i, "value " + std::to_string(values.size() + 1) +
                                 ": blank field in column " + std::to_string(at + 1));
            }
            if (tokens.size() > 1)
                text.fail(i, "value " + std::to_string(values.size() + 1) + ": field " +
                                 quotedToken(field) + " does not fit the " + std::to_string(w) +
                                 "-character format");
            values.push_back(
                finiteAt(text, i, tokens.front(), "value " + std::to_string(values.size() + 1)));
        }
    }
    if (values.size() < n)
        text.fail(i == 0 ? 0 : (i < text.size() ? i : i - 1),
                  "data end after " + std::to_string(values.size()) + " of " + std::to_string(n) +
                      " values announced by the header");
    next = i;
    return values;
}

} // namespace kinstab
