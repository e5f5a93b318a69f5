// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/base/UnitSystem.h"

#include "core/base/NameTable.h"

#include <charconv>
#include <cmath>

namespace kinstab {

std::string lengthUnitSymbol(UnitSystem s, LengthScale scale) {
    if (s == UnitSystem::US) return scale == LengthScale::Structure ? "ft" : "in";
    return scale == LengthScale::Structure ? "m" : "mm";
}

int lengthDecimals(UnitSystem s, LengthScale scale) {
    // A wall's width to 0.1 mm tells 192.2 mm (t* = 0.099 s) from 193.7 mm (7⅝ in); a storey
    // to the millimetre; US lengths to the hundredth, as drawings dimension them.
    if (s == UnitSystem::SI) return scale == LengthScale::Structure ? 3 : 1;
    return 2;
}

std::string lengthText(double metres, UnitSystem s, LengthScale scale) {
    const double v = metres / metresPerUnit(s, scale);
    if (!std::isfinite(v)) return "—";
    char buf[64];
    // to_chars ignores the locale: "192.2" under de_DE too (Qt sets the process locale).
    const auto r =
        std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, lengthDecimals(s, scale));
    std::string t(buf, r.ec == std::errc() ? r.ptr : buf);
    if (t.find('.') != std::string::npos) {
        while (t.back() == '0')
            t.pop_back();
        if (t.back() == '.') t.pop_back();
    }
    return t == "-0" ? "0" : t;
}

// UnitSystem's names, in its declaration order (SI, US).
constexpr std::array<const char*, 2> kUnitSystemNames = {"si", "us"};
static_assert(kUnitSystemNames.size() == static_cast<std::size_t>(UnitSystem::US) + 1);

std::string unitSystemName(UnitSystem s) {
    return enumName(kUnitSystemNames, s);
}

std::optional<UnitSystem> unitSystemFromName(const std::string& name) {
    // The names, or the same in capitals ("SI", "US").
    if (auto s = enumFromName<UnitSystem>(kUnitSystemNames, name)) return s;
    for (UnitSystem s : {UnitSystem::SI, UnitSystem::US})
        if (name == (s == UnitSystem::SI ? "SI" : "US")) return s;
    return std::nullopt;
}

} // namespace kinstab
