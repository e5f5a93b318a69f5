// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/base/UnitSystem.h"

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

std::string unitSystemName(UnitSystem s) {
    return s == UnitSystem::US ? "us" : "si";
}

std::optional<UnitSystem> unitSystemFromName(const std::string& name) {
    if (name == "si" || name == "SI") return UnitSystem::SI;
    if (name == "us" || name == "US") return UnitSystem::US;
    return std::nullopt;
}

} // namespace kinstab
