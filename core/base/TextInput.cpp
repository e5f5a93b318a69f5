// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/base/TextInput.h"

#include "core/base/InputLimits.h"

#include <charconv>
#include <filesystem>
#include <fstream>

namespace kinstab {

FileText readTextFile(const std::string& path, std::uintmax_t maxBytes) {
    const std::string limit = maxBytes >= (1u << 20) ? std::to_string(maxBytes >> 20) + " MB"
                                                     : std::to_string(maxBytes) + " bytes";
    const std::string tooLarge = "larger than the limit of " + limit + " for this kind of file";
    // A path is handed to the system as a C string: a NUL would cut it short and open another
    // file than the one named.
    if (path.find('\0') != std::string::npos) return {{}, "the path contains a NUL character"};
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return {{}, "is a folder, not a file"};
    const bool regular = std::filesystem::is_regular_file(path, ec);
    const std::uintmax_t size = regular ? std::filesystem::file_size(path, ec) : 0;
    if (regular && !ec && size > maxBytes) return {{}, tooLarge}; // refused unread
    std::ifstream in(path, std::ios::binary);
    if (!in) return {{}, "cannot open the file"};
    FileText f;
    char chunk[1 << 16];
    // A regular file's size is known and within the limit. A device or FIFO has none: its text
    // grows as it is read and reading stops one chunk past the limit (reserving the limit up
    // front took 10 GB for /dev/zero as study results).
    if (regular && !ec) f.text.reserve(size);
    while (in) {
        in.read(chunk, sizeof chunk);
        f.text.append(chunk, static_cast<std::size_t>(in.gcount()));
        if (f.text.size() > maxBytes) return {{}, tooLarge};
    }
    if (in.bad()) return {{}, "cannot read the file"};
    return f;
}

std::string_view trimmedView(std::string_view text) {
    const auto b = text.find_first_not_of(" \t\r\n");
    if (b == std::string_view::npos) return {};
    return text.substr(b, text.find_last_not_of(" \t\r\n") - b + 1);
}

std::string trimmed(std::string_view text) {
    return std::string(trimmedView(text));
}

std::string_view withoutBom(std::string_view text) {
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    return text;
}

namespace {
// Length of the UTF-8 sequence starting at s[i], or 0 when it is not well formed (overlong
// forms, surrogates and code points above U+10FFFF are not).
std::size_t utf8Length(std::string_view s, std::size_t i) {
    const auto b = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char c = b(i);
    if (c < 0x80) return 1;
    std::size_t n = 0;
    unsigned char lo = 0x80, hi = 0xBF; // allowed range of the second byte
    if (c >= 0xC2 && c <= 0xDF)
        n = 2;
    else if (c >= 0xE0 && c <= 0xEF) {
        n = 3;
        if (c == 0xE0) lo = 0xA0;
        if (c == 0xED) hi = 0x9F;
    } else if (c >= 0xF0 && c <= 0xF4) {
        n = 4;
        if (c == 0xF0) lo = 0x90;
        if (c == 0xF4) hi = 0x8F;
    } else
        return 0;
    if (i + n > s.size() || b(i + 1) < lo || b(i + 1) > hi) return 0;
    for (std::size_t k = 2; k < n; ++k)
        if ((b(i + k) & 0xC0) != 0x80) return 0;
    return n;
}
} // namespace

bool isValidUtf8(std::string_view text) {
    for (std::size_t i = 0; i < text.size();) {
        const std::size_t n = utf8Length(text, i);
        if (n == 0) return false;
        i += n;
    }
    return true;
}

std::string utf8FromLegacy(std::string_view text) {
    if (isValidUtf8(text)) return std::string(text);
    std::string out;
    out.reserve(text.size() + text.size() / 8);
    for (const char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        if (c < 0x80) {
            out += ch;
        } else { // Latin-1 byte c is the code point c: two UTF-8 bytes
            out += static_cast<char>(0xC0 | (c >> 6));
            out += static_cast<char>(0x80 | (c & 0x3F));
        }
    }
    return out;
}

std::string elided(std::string_view text, std::size_t maxChars) {
    std::size_t chars = 0, i = 0;
    while (i < text.size() && chars < maxChars) {
        const std::size_t n = utf8Length(text, i);
        i += n == 0 ? 1 : n;
        ++chars;
    }
    if (i >= text.size()) return std::string(text);
    return std::string(text.substr(0, i)) + "...";
}

std::string quotedToken(std::string_view token) {
    return "'" + elided(token, limits::kMaxQuotedChars) + "'";
}

std::string nulShown(std::string_view text) {
    std::string s;
    for (char c : text)
        s += c == '\0' ? std::string("\\0") : std::string(1, c);
    return s;
}

std::optional<double> parseDouble(std::string_view token) {
    if (!token.empty() && token.front() == '+') {
        token.remove_prefix(1); // "+1.5" as from_chars does not, but never "+-1" or "++1"
        if (token.empty() || token.front() == '+' || token.front() == '-') return std::nullopt;
    }
    if (token.empty()) return std::nullopt;
    double x = 0;
    const char* end = token.data() + token.size();
    const auto [at, ec] = std::from_chars(token.data(), end, x);
    if (ec != std::errc() || at != end) return std::nullopt;
    return x;
}

std::optional<std::size_t> parseCount(std::string_view token, std::size_t max) {
    if (token.empty() || token.size() > 19) return std::nullopt; // beyond 19 digits: overflow
    std::size_t n = 0;
    for (const char c : token) {
        if (c < '0' || c > '9') return std::nullopt;
        n = n * 10 + static_cast<std::size_t>(c - '0');
    }
    if (n > max) return std::nullopt;
    return n;
}

std::string formatDouble(double x) {
    char buffer[32];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, x);
    return ec == std::errc() ? std::string(buffer, end) : std::string("?");
}

} // namespace kinstab
