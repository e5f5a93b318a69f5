// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/base/DisplayText.h"

#include "core/base/TextInput.h"

#include <cstdio>
#include <optional>

namespace kinstab {

namespace {

// Bytes of the sequence a lead byte announces; isValidUtf8 judges whether they form one.
std::size_t announcedLength(unsigned char lead) {
    return lead < 0x80 ? 1 : lead < 0xE0 ? 2 : lead < 0xF0 ? 3 : 4;
}

// The code point at text[i] and its length in bytes; none when no valid sequence starts there.
std::optional<std::pair<char32_t, std::size_t>> decodeAt(std::string_view text, std::size_t i) {
    const auto lead = static_cast<unsigned char>(text[i]);
    const std::size_t n = announcedLength(lead);
    if (i + n > text.size() || !isValidUtf8(text.substr(i, n))) return std::nullopt;
    if (n == 1) return std::pair{char32_t{lead}, n};
    char32_t cp = lead & (0xFF >> (n + 1));
    for (std::size_t k = 1; k < n; ++k)
        cp = (cp << 6) | (static_cast<unsigned char>(text[i + k]) & 0x3F);
    return std::pair{cp, n};
}

bool isLineBreak(char32_t c) {
    return c == U'\n' || c == U'\r' || c == U'\u2028' || c == U'\u2029';
}

// What the code point is when it may not stand in the text; nullptr when it may.
const char* refusedKind(char32_t c, TextLines lines) {
    if (isLineBreak(c))
        return lines == TextLines::Single ? "a line break in one-line text" : nullptr;
    if (c == U'\0') return "NUL";
    if (c == U'\t') return nullptr;
    if (c < 0x20 || (c >= 0x7F && c <= 0x9F)) return "a control character";
    if (c == U'\u202D' || c == U'\u202E') return "a bidirectional override";
    if (c >= U'\u202A' && c <= U'\u202C') return "a bidirectional embedding";
    if (c >= U'\u2066' && c <= U'\u2069') return "a bidirectional isolate";
    if (c == U'\u200E' || c == U'\u200F' || c == U'\u061C') return "a bidirectional mark";
    return nullptr;
}

std::string codePointName(char32_t c) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "U+%04X", static_cast<unsigned>(c));
    return buf;
}

} // namespace

std::size_t utf8Chars(std::string_view text) {
    std::size_t chars = 0;
    for (std::size_t i = 0; i < text.size(); ++chars) {
        const auto d = decodeAt(text, i);
        i += d ? d->second : 1;
    }
    return chars;
}

std::string displayTextProblem(std::string_view text, std::size_t maxChars, TextLines lines) {
    if (const std::size_t n = utf8Chars(text); n > maxChars)
        return std::to_string(n) + " characters, more than the limit of " +
               std::to_string(maxChars);
    std::size_t at = 1; // characters counted from 1, as a reader counts them
    for (std::size_t i = 0; i < text.size(); ++at) {
        const auto d = decodeAt(text, i);
        if (!d) return "is not UTF-8 text (a stray byte at character " + std::to_string(at) + ")";
        if (const char* kind = refusedKind(d->first, lines))
            return "contains " + codePointName(d->first) + " (" + kind + ") at character " +
                   std::to_string(at);
        i += d->second;
    }
    return {};
}

std::string checkDisplayText(const std::string& field, std::string_view text, std::size_t maxChars,
                             TextLines lines) {
    const std::string problem = displayTextProblem(text, maxChars, lines);
    return problem.empty() ? problem : field + ": " + problem;
}

} // namespace kinstab
