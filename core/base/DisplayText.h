// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Free text that a person reads on a signed document (a project's name and description, the
// building's name, the title-block fields of core/io/ProjectInfo.h): what may stand in it, and
// how long it may be, in characters (Unicode code points) as a reader counts them, not bytes.
//
// Refused, with the code point and its position named:
//  - text that is not UTF-8;
//  - C0 control characters (U+0000-U+001F) but tab, DEL (U+007F) and the C1 controls
//    (U+0080-U+009F): NUL cuts the text short in C strings, ESC and BEL reach the PDF's text;
//  - the Unicode bidirectional formatting characters: embeddings, overrides and their end
//    (U+202A-U+202E), isolates (U+2066-U+2069) and the marks U+200E, U+200F and U+061C. An
//    override shows "S 12345<U+202E>67890" as "S 1234509876" on the title block; the marks are
//    invisible too and move the neutral characters next to them (the digits, dashes and slashes
//    of a registration number or a date). Right-to-left text (Hebrew, Arabic) needs none of them
//    on the report's one-direction lines, so every one of them is refused rather than some;
//  - line breaks (LF, CR, U+2028, U+2029) in single-line text: a name is one line of a title
//    block; a multi-line text (a description) keeps them.

#include <cstddef>
#include <string>
#include <string_view>

namespace kinstab {

enum class TextLines { Single, Multiple };

// Characters (code points) of UTF-8 text; a byte that starts no valid sequence counts as one.
std::size_t utf8Chars(std::string_view text);

// Empty when the text may stand on a report; else why not, without a field name:
// "201 characters, more than the limit of 200" or
// "contains U+202E (a bidirectional override) at character 8" (characters counted from 1).
std::string displayTextProblem(std::string_view text, std::size_t maxChars, TextLines lines);

// "field: " + displayTextProblem(...), or empty when fine.
std::string checkDisplayText(const std::string& field, std::string_view text, std::size_t maxChars,
                             TextLines lines = TextLines::Single);

} // namespace kinstab
