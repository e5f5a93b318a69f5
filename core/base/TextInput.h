// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What every reader of a text file shares: a size-bounded read, the UTF-8 byte-order mark
// that Excel and Notepad write, header text that is not UTF-8 (old records are Latin-1),
// locale-independent numbers, and short quotes of bad input for messages.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace kinstab {

// The bytes of a file, or an error ("cannot open the file", "larger than the limit of N
// MB", "the path contains a NUL character"). Reads at most maxBytes + one chunk, and reserves
// memory only for a regular file's known size, so /dev/zero or a FIFO cannot exhaust memory.
struct FileText {
    std::string text;
    std::string error; // empty when fine
};
FileText readTextFile(const std::string& path, std::uintmax_t maxBytes);

// Text without its leading and trailing blanks (space, tab, CR, LF): the one trim of every
// reader (a CRLF file's lines end in CR).
std::string_view trimmedView(std::string_view text);
std::string trimmed(std::string_view text);

// Drops a leading UTF-8 byte-order mark (EF BB BF).
std::string_view withoutBom(std::string_view text);
bool isValidUtf8(std::string_view text);
// The text as UTF-8: unchanged when it is valid UTF-8, else read as Latin-1 (ISO 8859-1) and
// transcoded, so "M\xE9xico" becomes "México".
std::string utf8FromLegacy(std::string_view text);

// At most maxChars characters (UTF-8 code points) of text, with "..." when cut.
std::string elided(std::string_view text, std::size_t maxChars);
// A token for an error message: elided to limits::kMaxQuotedChars and in single quotes.
std::string quotedToken(std::string_view token);
// The text with each NUL character shown as \0: an exception's message is a C string, which a
// NUL in a path (refused, but named) would end where it stands.
std::string nulShown(std::string_view text);

// A whole token as a finite or infinite double, in the C locale's syntax whatever the
// process locale ("1.5", "-2e-3"); a leading '+' is allowed. Nothing on any other text.
std::optional<double> parseDouble(std::string_view token);
// A whole token of decimal digits as a count no larger than max, or nothing.
std::optional<std::size_t> parseCount(std::string_view token, std::size_t max);
// Shortest text that reads back as the same double, in the C locale ("0.1", "1e-07").
std::string formatDouble(double x);

} // namespace kinstab
