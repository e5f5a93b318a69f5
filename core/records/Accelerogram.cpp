// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/records/Accelerogram.h"

#include "core/base/NameTable.h"

#include "core/base/PhysicalConstants.h"
#include "core/base/TextInput.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

namespace kinstab {

namespace {} // namespace

// AccelUnit's names, in its declaration order (G, MetresPerS2, CmPerS2, FtPerS2, InPerS2).
constexpr std::array<const char*, 5> kAccelUnitNames = {"g", "m/s2", "cm/s2", "ft/s2", "in/s2"};
static_assert(kAccelUnitNames.size() == static_cast<std::size_t>(AccelUnit::InPerS2) + 1);

std::string accelUnitName(AccelUnit u) {
    return enumName(kAccelUnitNames, u);
}

std::optional<AccelUnit> accelUnitFromName(const std::string& name) {
    std::string k;
    for (char c : name)
        if (!std::isspace(static_cast<unsigned char>(c)))
            k += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    static const std::map<std::string, AccelUnit> names = {
        {"g", AccelUnit::G},
        {"m/s2", AccelUnit::MetresPerS2},
        {"m/s^2", AccelUnit::MetresPerS2},
        {"m/sec2", AccelUnit::MetresPerS2},
        {"m/s/s", AccelUnit::MetresPerS2},
        {"cm/s2", AccelUnit::CmPerS2},
        {"cm/s^2", AccelUnit::CmPerS2},
        {"cm/sec2", AccelUnit::CmPerS2},
        {"cm/sec/sec", AccelUnit::CmPerS2},
        {"cm/s/s", AccelUnit::CmPerS2},
        {"gal", AccelUnit::CmPerS2},
        {"ft/s2", AccelUnit::FtPerS2},
        {"ft/s^2", AccelUnit::FtPerS2},
        {"ft/sec2", AccelUnit::FtPerS2},
        {"in/s2", AccelUnit::InPerS2},
        {"in/s^2", AccelUnit::InPerS2},
        {"in/sec2", AccelUnit::InPerS2},
    };
    const auto it = names.find(k);
    if (it == names.end()) return std::nullopt;
    return it->second;
}

double gPerUnit(AccelUnit u) {
    switch (u) {
    case AccelUnit::G:
        return 1.0;
    case AccelUnit::MetresPerS2:
        return 1.0 / kStandardGravity;
    case AccelUnit::CmPerS2:
        return 0.01 / kStandardGravity;
    case AccelUnit::FtPerS2:
        return 0.3048 / kStandardGravity; // international foot
    case AccelUnit::InPerS2:
        return 0.0254 / kStandardGravity;
    }
    return 1.0;
}

double Accelerogram::duration() const {
    return samples.empty() ? 0.0 : dt * static_cast<double>(samples.size() - 1);
}

SignedPeak Accelerogram::peak() const {
    SignedPeak p;
    for (std::size_t i = 0; i < samples.size(); ++i)
        if (std::abs(samples[i]) > std::abs(p.value))
            p = {samples[i], dt * static_cast<double>(i), i};
    return p;
}

RecordError::RecordError(const std::string& file, int line, const std::string& message)
    : std::runtime_error(nulShown(file) + ":" + std::to_string(line) + ": " + message), file_(file),
      line_(line), message_(message) {}

void validateAccelerogram(const Accelerogram& a) {
    if (!(a.dt > 0.0) || !std::isfinite(a.dt))
        throw RecordError(a.sourceFile, 0,
                          "time step dt = " + formatDouble(a.dt) + " s: must be > 0");
    if (a.samples.size() < 2)
        throw RecordError(a.sourceFile, 0,
                          "record has " + std::to_string(a.samples.size()) +
                              " samples: need at least 2");
    const auto bad = std::find_if(a.samples.begin(), a.samples.end(),
                                  [](double x) { return !std::isfinite(x); });
    if (bad != a.samples.end())
        throw RecordError(a.sourceFile, 0,
                          "sample " + std::to_string(bad - a.samples.begin()) +
                              " is not a finite number");
}

} // namespace kinstab
