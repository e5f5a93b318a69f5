// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/codes/CodeCatalog.h"

#include <array>

namespace kinstab {

namespace {

constexpr std::array<CodeInfo, 5> catalog{{
    {CodeKey::Ubc1976, "ubc1976", "UBC 1976", "UBC 1976 §2312",
     "Uniform Building Code, 1976 edition, §2312, International Conference of Building "
     "Officials, Whittier, California.",
     0xC81EA0},
    {CodeKey::Atc306, "atc306", "ATC 3-06", "ATC 3-06 (1978) §4.2",
     "ATC 3-06, Tentative Provisions for the Development of Seismic Regulations for Buildings, "
     "Applied Technology Council, 1978 (NBS SP 510).",
     0xF08200},
    {CodeKey::Ubc1997, "ubc1997", "UBC 1997", "UBC 1997 §1630.2 (strength level)",
     "Uniform Building Code, 1997 edition, vol. 2, §1630, International Conference of Building "
     "Officials.",
     0x7846C8},
    {CodeKey::Asce7_22, "asce7_22", "ASCE 7-22", "ASCE/SEI 7-22 §12.8 (equivalent lateral force)",
     "ASCE/SEI 7-22, Minimum Design Loads and Associated Criteria for Buildings and Other "
     "Structures, ch. 11–12, American Society of Civil Engineers, 2022.",
     0x009646},
    {CodeKey::Ec8, "ec8", "EC8", "EN 1998-1:2004 §4.3.3.2 (lateral force method)",
     "EN 1998-1:2004, Eurocode 8: Design of structures for earthquake resistance, Part 1, §3.2 "
     "and §4.3.3.2, CEN.",
     0x0078C8},
}};

} // namespace

std::span<const CodeInfo> codeCatalog() {
    return catalog;
}

const CodeInfo& codeInfo(CodeKey key) {
    return catalog[static_cast<std::size_t>(key)];
}

const CodeInfo* findCode(std::string_view id) {
    for (const CodeInfo& c : catalog)
        if (c.id == id) return &c;
    return nullptr;
}

} // namespace kinstab
