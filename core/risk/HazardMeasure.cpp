// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/risk/HazardMeasure.h"

#include "core/base/TextInput.h"

#include <algorithm>
#include <cmath>
#include <string_view>

namespace kinstab {

namespace {

std::optional<HazardMeasure> saOf(std::string_view period) {
    const std::optional<double> t = parseDouble(period);
    if (!t || !std::isfinite(*t) || !(*t > 0.0)) return std::nullopt;
    return HazardMeasure{HazardMeasure::Kind::Sa, *t};
}

bool startsWith(std::string_view s, std::string_view prefix) {
    return s.substr(0, prefix.size()) == prefix;
}

} // namespace

std::string hazardMeasureName(const HazardMeasure& m) {
    switch (m.kind) {
    case HazardMeasure::Kind::Pga:
        return "PGA";
    case HazardMeasure::Kind::Sa:
        return "SA(" + formatDouble(m.periodS) + " s)";
    case HazardMeasure::Kind::Unstated:
        break;
    }
    return "unstated";
}

std::optional<HazardMeasure> measureFromOpenQuake(const std::string& imt) {
    if (imt == "PGA") return HazardMeasure{HazardMeasure::Kind::Pga, 0.0};
    const std::string_view s(imt);
    if (!startsWith(s, "SA(") || s.size() < 5 || s.back() != ')') return std::nullopt;
    return saOf(s.substr(3, s.size() - 4));
}

// The USGS writes the period with P for the decimal point: SA0P2 is Sa(0.2 s), SA10P0 Sa(10 s).
std::optional<HazardMeasure> measureFromUsgs(const std::string& imt) {
    if (imt == "PGA") return HazardMeasure{HazardMeasure::Kind::Pga, 0.0};
    const std::string_view s(imt);
    const std::size_t p = s.find('P', 2);
    if (!startsWith(s, "SA") || p == std::string_view::npos || p == 2 || p + 1 == s.size())
        return std::nullopt;
    for (std::size_t i = 2; i < s.size(); ++i)
        if (i != p && (s[i] < '0' || s[i] > '9')) return std::nullopt;
    return saOf(std::string(s.substr(2, p - 2)) + "." + std::string(s.substr(p + 1)));
}

std::optional<HazardMeasure> measureFromStudy(const std::string& name) {
    if (name == "pga") return HazardMeasure{HazardMeasure::Kind::Pga, 0.0};
    const std::string_view s(name);
    const std::size_t unit = s.find("s/");
    if (!startsWith(s, "sa(") || unit == std::string_view::npos || s.substr(unit) != "s/5%)")
        return std::nullopt;
    return saOf(s.substr(3, unit - 3));
}

bool sameMeasure(const HazardMeasure& a, const HazardMeasure& b) {
    if (a.kind != b.kind) return false;
    return a.kind != HazardMeasure::Kind::Sa ||
           std::abs(a.periodS - b.periodS) <= 1e-9 * std::max(a.periodS, b.periodS);
}

} // namespace kinstab
