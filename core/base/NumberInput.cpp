// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/base/NumberInput.h"

#include "core/base/TextInput.h"

namespace kinstab {

std::string flagName(std::string_view key) {
    std::string f = "--" + std::string(key);
    for (char& c : f)
        if (c == '_') c = '-';
    return f;
}

std::string flagName(const NumberInput& in) {
    return in.flag.empty() ? flagName(in.key) : "--" + std::string(in.flag);
}

std::string rangeText(const NumberInput& in) {
    const std::string unit = in.unit.empty() ? "" : " " + std::string(in.unit);
    const Range& r = in.range;
    if (r.loOpen) return "> " + formatDouble(r.lo) + " and at most " + formatDouble(r.hi) + unit;
    return "between " + formatDouble(r.lo) + " and " + formatDouble(r.hi) + unit;
}

InputProblem checkInput(const NumberInput& in, double x) {
    if (in.range.contains(x)) return {};
    return {std::string(in.key), x, std::string(in.unit),
            std::string(in.what) + " must be " + rangeText(in)};
}

std::string valueAndWhy(const InputProblem& p) {
    return formatDouble(p.value) + (p.unit.empty() ? "" : " " + p.unit) + ": " + p.why;
}

std::string describeAs(const InputProblem& p, std::string_view name) {
    if (p.empty()) return {};
    return std::string(name) + " = " + valueAndWhy(p);
}

std::string describe(const InputProblem& p, std::string_view prefix) {
    return describeAs(p, std::string(prefix) + p.key);
}

} // namespace kinstab
