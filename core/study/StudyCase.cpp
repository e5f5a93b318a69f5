// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/StudyCase.h"

#include "core/base/TextInput.h"

namespace kinstab {

std::size_t studyParameterSets(const StudySpec& s) {
    return s.mu.size() * s.tstar.size() * (s.floors.size() + s.levels.size()) * s.motions.size();
}

std::size_t studyCasesPerSet(const StudySpec& s) {
    return s.records.size() * (s.bothPolarities ? 2 : 1);
}

std::size_t studyCaseCount(const StudySpec& s) {
    return studyParameterSets(s) * studyCasesPerSet(s);
}

StudyCase studyCase(const StudySpec& s, std::size_t index) {
    StudyCase c;
    c.index = index;
    const std::size_t polarities = s.bothPolarities ? 2 : 1;
    const std::size_t inSet = index % studyCasesPerSet(s);
    c.record = &s.records[inSet / polarities];
    c.inverted = inSet % polarities == 1;
    c.set = index / studyCasesPerSet(s);
    std::size_t rest = c.set;
    c.motion = s.motions[rest % s.motions.size()];
    rest /= s.motions.size();
    const std::size_t drivers = s.floors.size() + s.levels.size();
    const std::size_t driver = rest % drivers;
    if (driver < s.floors.size())
        c.floor = s.floors[driver];
    else
        c.level = s.levels[driver - s.floors.size()];
    rest /= drivers;
    c.tstar = s.tstar[rest % s.tstar.size()];
    rest /= s.tstar.size();
    c.mu = s.mu[rest];
    return c;
}

std::optional<Shard> parseShard(const std::string& text) {
    const auto slash = text.find('/');
    if (slash == std::string::npos) return std::nullopt;
    const auto k = parseCount(std::string_view(text).substr(0, slash), kMaxStudyCases);
    const auto n = parseCount(std::string_view(text).substr(slash + 1), kMaxStudyCases);
    if (!k || !n || *k < 1 || *k > *n) return std::nullopt;
    return Shard{*k, *n};
}

StudyRow studyRowInputs(const StudySpec& s, const StudyCase& c) {
    StudyRow row;
    row.index = c.index;
    row.cases = studyCaseCount(s);
    row.study = s.fingerprint;
    row.set = c.set;
    row.record = c.record->label;
    if (s.block) {
        row.block = s.block;
    } else {
        row.mu = c.mu;
        row.tstar = c.tstar;
        row.limit = s.limit;
    }
    if (c.floor) {
        row.floorPeriod = c.floor->period;
        row.floorDamping = c.floor->damping;
    }
    if (c.level > 0) row.level = c.level;
    if (s.motionGiven) row.motion = motionName(c.motion);
    if (s.bothPolarities) row.polarity = c.inverted ? "inverted" : "normal";
    row.measure = intensityName(s.intensity);
    return row;
}

} // namespace kinstab
