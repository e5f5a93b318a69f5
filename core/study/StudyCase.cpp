// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/StudyCase.h"

#include "core/base/TextInput.h"

namespace kinstab {

std::size_t studyParameterSets(const StudySpec& s) {
    return s.mu.size() * s.tstar.size() * s.floors.size();
}

std::size_t studyCaseCount(const StudySpec& s) {
    return studyParameterSets(s) * s.records.size();
}

StudyCase studyCase(const StudySpec& s, std::size_t index) {
    StudyCase c;
    c.index = index;
    c.record = &s.records[index % s.records.size()];
    c.set = index / s.records.size();
    std::size_t rest = c.set;
    c.floor = s.floors[rest % s.floors.size()];
    rest /= s.floors.size();
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

} // namespace kinstab
