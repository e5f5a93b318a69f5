// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/codes/CodeSet.h"

#include "core/codes/CodeCatalog.h"

namespace kinstab {

std::vector<std::string> codeKeys() {
    std::vector<std::string> keys;
    for (const CodeInfo& c : codeCatalog())
        keys.emplace_back(c.id);
    return keys;
}

bool isSelected(const CodeSelection& c, std::string_view id) {
    if (id == "ubc1976") return c.ubc1976.has_value();
    if (id == "atc306") return c.atc306.has_value();
    if (id == "ubc1997") return c.ubc1997.has_value();
    if (id == "asce7_22") return c.asce7_22.has_value();
    return id == "ec8" && c.ec8.has_value();
}

std::string validateCodes(const CodeSelection& c) {
    std::string e;
    if (e.empty() && c.ubc1976) e = validateUbc1976(*c.ubc1976);
    if (e.empty() && c.atc306) e = validateAtc306(*c.atc306);
    if (e.empty() && c.ubc1997) e = validateUbc1997(*c.ubc1997);
    if (e.empty() && c.asce7_22) e = validateAsce7(*c.asce7_22);
    if (e.empty() && c.ec8) e = validateEurocode8(*c.ec8);
    return e;
}

std::vector<CodeResult> runCodes(const Building& b, const CodeSelection& c) {
    // Validate everything first: nothing is computed when any input is bad.
    requireValidBuilding(b);
    if (const std::string e = validateCodes(c); !e.empty()) throw InputError(e);
    std::vector<CodeResult> out;
    if (c.ubc1976) out.push_back(ubc1976(b, *c.ubc1976));
    if (c.atc306) out.push_back(atc306(b, *c.atc306));
    if (c.ubc1997) out.push_back(ubc1997(b, *c.ubc1997));
    if (c.asce7_22) out.push_back(asce7_22(b, *c.asce7_22));
    if (c.ec8) out.push_back(eurocode8(b, *c.ec8));
    return out;
}

} // namespace kinstab
