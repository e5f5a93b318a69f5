// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What kinstab says about each building code it implements, written once: the JSON key, the
// short name for legends, the clause the ratio comes from, the full reference and the colour
// that stands for the code in every chart and report figure.

#include <cstdint>
#include <span>
#include <string_view>

namespace kinstab {

enum class CodeKey { Ubc1976, Atc306, Ubc1997, Asce7_22, Ec8 };

struct CodeInfo {
    CodeKey key;
    std::string_view id;        // JSON key: "ubc1976"
    std::string_view shortName; // legends and table rows: "UBC 1976"
    std::string_view title;     // the clause the ratio comes from: "UBC 1976 §2312"
    std::string_view citation;  // reference list entry
    std::uint32_t rgb;          // 0xRRGGBB, the code's colour in the GUI and the report
};

// All codes, in output order (the order of CodeSelection and of every table).
std::span<const CodeInfo> codeCatalog();
const CodeInfo& codeInfo(CodeKey key);
// nullptr when `id` names no code.
const CodeInfo* findCode(std::string_view id);

} // namespace kinstab
