// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/StudyFingerprint.h"

#include "core/base/Sha256.h"
#include "core/base/TextInput.h"

#include <stdexcept>

namespace kinstab {

namespace {

std::string list(const std::vector<double>& v) {
    std::string s;
    for (double x : v)
        s += formatDouble(x) + ",";
    return s;
}

std::string optionalNumber(const std::optional<double>& x) {
    return x ? formatDouble(*x) : std::string("none");
}

// The building as the study file gives it (not its modes, which are computed: a shard on
// another machine may round them otherwise).
std::string buildingText(const StudySpec& s) {
    if (!s.building) return "none";
    const Building& b = s.building->building;
    return std::to_string(b.stories) + " " + unitName(b.unit) + " " + formatDouble(b.height) + " " +
           formatDouble(b.planDimension) + " " + optionalNumber(b.period) + " " +
           systemName(b.system) + " " + occupancyName(b.occupancy) + " [" + list(b.storyWeights) +
           "] [" + list(b.storyHeights) + "] " + stiffnessName(s.building->settings.stiffness) +
           " " + formatDouble(s.building->settings.damping);
}

std::string driversText(const StudySpec& s) {
    std::string d;
    for (const auto& f : s.floors)
        d += f ? "floor " + formatDouble(f->period) + " " + formatDouble(f->damping) + ";"
               : std::string("ground;");
    for (int level : s.levels)
        d += "level " + std::to_string(level) + ";";
    return d;
}

// One line per input, numbers as the shortest text that reads back the same double: the same
// study gives the same text on every machine and in every locale.
std::string canonicalText(const StudySpec& s) {
    std::string t = "kinstab-study-fingerprint 1\n";
    t += "intensity " + intensityName(s.intensity) + " " + formatDouble(s.intensity.period) + " " +
         formatDouble(s.intensity.damping) + "\n";
    t +=
        "mu " + list(s.mu) + "\ntstar " + list(s.tstar) + "\nlimit " + formatDouble(s.limit) + "\n";
    t += "drivers " + driversText(s) + "\nbuilding " + buildingText(s) + "\n";
    t += "motions " + std::string(s.motionGiven ? "named " : "unnamed ");
    for (StudyMotion m : s.motions)
        t += motionName(m) + ",";
    t += "\nsearch " + formatDouble(s.search.from) + " " + formatDouble(s.search.to) + " " +
         formatDouble(s.search.scanStep) + " " + formatDouble(s.search.tolerance) + "\n";
    t += "as_given " + std::string(s.asGiven ? "yes" : "no") + "\n";
    // Only a study of both polarities says so: older studies keep their fingerprints.
    if (s.bothPolarities) t += "polarity both\n";
    if (s.block) t += "block " + studyBlockText(*s.block) + "\n";
    for (const StudyRecord& r : s.records) {
        if (r.sha256.empty()) throw std::logic_error("study fingerprint: records not read");
        t += "record " + r.sha256 + " " + formatDouble(r.scale) + "\n";
    }
    return t;
}

} // namespace

std::string studyFingerprint(const StudySpec& s) {
    return sha256Hex(canonicalText(s)).substr(0, kStudyFingerprintDigits);
}

bool isStudyFingerprint(std::string_view text) {
    if (text.size() != kStudyFingerprintDigits) return false;
    for (char c : text)
        if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
    return true;
}

} // namespace kinstab
