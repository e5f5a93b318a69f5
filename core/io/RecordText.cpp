#include "core/io/RecordText.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace kinstab {

RecordText::RecordText(const std::string& text, std::string source) : source_(std::move(source)) {
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(start, end - start);
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines_.push_back(std::move(line));
        start = end + 1;
    }
}

RecordText RecordText::fromFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw RecordError(path, 0, "cannot open the file");
    std::ostringstream s;
    s << in.rdbuf();
    if (in.bad()) throw RecordError(path, 0, "cannot read the file");
    return RecordText(s.str(), path);
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
    if (!token.empty() && token.front() == '+') token.remove_prefix(1);
    if (token.empty() || token.front() == '+') return std::nullopt;
    std::string t(token);
    for (char& c : t)
        if (c == 'D' || c == 'd') c = 'E'; // Fortran double-precision exponent
    double x = 0;
    const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), x);
    if (ec != std::errc() || end != t.data() + t.size()) return std::nullopt;
    return x;
}

double finiteAt(const RecordText& text, std::size_t i, std::string_view token,
                const std::string& what) {
    const std::optional<double> x = parseNumber(token);
    if (!x) text.fail(i, what + " '" + std::string(token) + "' is not a number");
    if (!std::isfinite(*x))
        text.fail(i, what + " '" + std::string(token) + "' is not a finite number");
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

std::string trimmed(const std::string& s) {
    const std::size_t a = s.find_first_not_of(" \t");
    if (a == std::string::npos) return {};
    return s.substr(a, s.find_last_not_of(" \t") - a + 1);
}

std::vector<double> readFreeValues(const RecordText& text, std::size_t first) {
    std::vector<double> values;
    for (std::size_t i = first; i < text.size(); ++i)
        for (std::string_view token : splitWhitespace(text.line(i)))
            values.push_back(
                finiteAt(text, i, token, "value " + std::to_string(values.size() + 1)));
    return values;
}

std::optional<FixedFormat> parseFortranFormat(std::string_view spec) {
    // "(8f10.6)", "(1E15.6)", "Format=(1E15.6)": count, letter E/F, width.
    const std::size_t open = spec.find('(');
    if (open == std::string_view::npos) return std::nullopt;
    std::size_t i = open + 1;
    int count = 0;
    while (i < spec.size() && std::isdigit(static_cast<unsigned char>(spec[i])))
        count = count * 10 + (spec[i++] - '0');
    if (i >= spec.size() || (std::toupper(static_cast<unsigned char>(spec[i])) != 'E' &&
                             std::toupper(static_cast<unsigned char>(spec[i])) != 'F'))
        return std::nullopt;
    ++i;
    int width = 0;
    while (i < spec.size() && std::isdigit(static_cast<unsigned char>(spec[i])))
        width = width * 10 + (spec[i++] - '0');
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
    std::vector<double> values;
    values.reserve(n);
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
                text.fail(i, "value " + std::to_string(values.size() + 1) + ": field '" + field +
                                 "' does not fit the " + std::to_string(w) + "-character format");
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
