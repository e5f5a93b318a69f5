// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The text of an accelerogram file as numbered lines, and the number scanning every reader
// shares. Every failure is a RecordError naming the file and the 1-based line.

#include "core/records/Accelerogram.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace kinstab {

class RecordText {
public:
    // Splits text into lines; CR of CRLF line ends is dropped.
    RecordText(const std::string& text, std::string source);
    // Reads a whole file; a missing or unreadable file is a RecordError at line 0.
    static RecordText fromFile(const std::string& path);

    std::size_t size() const { return lines_.size(); }
    const std::string& line(std::size_t i) const { return lines_[i]; } // 0-based
    // The first kHeaderChars characters of line i: what header patterns are matched against.
    // std::regex recurses once per character, so a megabyte-long line would overflow the stack.
    std::string header(std::size_t i) const { return lines_[i].substr(0, kHeaderChars); }
    static constexpr std::size_t kHeaderChars = 1000;
    const std::string& source() const { return source_; }
    bool blank(std::size_t i) const;
    // Index of the first line at or after i that is not blank, or size().
    std::size_t skipBlank(std::size_t i) const;
    [[noreturn]] void fail(std::size_t i, const std::string& message) const; // line i (0-based)
    [[noreturn]] void failFile(const std::string& message) const;            // line 0

private:
    std::vector<std::string> lines_;
    std::string source_;
};

// A whole token as a number ("-.4486975E-03", "1.0D+00", "+3"), or nothing. NaN and infinity
// are returned as parsed: callers that need finite values check with finiteAt.
std::optional<double> parseNumber(std::string_view token);
// The token as a finite number, or a RecordError at line i naming `what` and the token.
double finiteAt(const RecordText& text, std::size_t i, std::string_view token,
                const std::string& what);
std::vector<std::string_view> splitWhitespace(std::string_view line);
std::string lowerCase(std::string s);

// Values separated by blanks, from line `first` to the end of the text (blank lines allowed).
std::vector<double> readFreeValues(const RecordText& text, std::size_t first);

// A Fortran data format such as "(8f10.6)" or "(1E15.6)": values per line and field width.
struct FixedFormat {
    int perLine = 8;
    int width = 10;
};
std::optional<FixedFormat> parseFortranFormat(std::string_view spec);

// Exactly n values in fixed-width fields from line `first` on; `next` gets the line after the
// last one used. A line that ends before n values is a truncation error naming the count found.
std::vector<double> readFixedValues(const RecordText& text, std::size_t first, std::size_t n,
                                    FixedFormat format, std::size_t& next);

} // namespace kinstab
