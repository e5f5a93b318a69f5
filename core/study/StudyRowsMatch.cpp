// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/StudyRowsMatch.h"

#include "core/base/TextInput.h"
#include "core/study/StudyCase.h"

#include <cmath>
#include <filesystem>
#include <optional>
#include <stdexcept>

namespace kinstab {

namespace {

namespace fs = std::filesystem;

// Rows are written with the shortest text that reads back as the same double, so equal inputs
// compare equal; the derived search limit carries a few roundings.
bool same(double a, double b, double rel = 0.0) {
    return a == b || std::abs(a - b) <= rel * std::max(std::abs(a), std::abs(b));
}

std::string text(double x) {
    return formatDouble(x);
}

std::string text(const std::optional<double>& x) {
    return x ? formatDouble(*x) : std::string("none");
}

// The record's file a row names: its label, relative to the study file unless absolute.
fs::path rowFile(const std::string& label, const std::string& studyDir) {
    const fs::path p(label);
    return (p.is_absolute() ? p : fs::path(studyDir) / p).lexically_normal();
}

std::string text(const std::optional<int>& level) {
    return level ? std::to_string(*level) : std::string("none");
}

std::string caseMismatch(const StudySpec& s, const std::string& dir, const StudyRow& r,
                         const StudyCase& c) {
    const StudyRow want = studyRowInputs(s, c); // what a run of the case writes
    if (rowFile(r.record, dir) != fs::path(c.record->file).lexically_normal())
        return "record " + r.record + ", the study file says " + want.record;
    if (r.block != want.block)
        return "block " + (r.block ? studyBlockText(*r.block) : std::string("none")) +
               ", the study file says " +
               (want.block ? studyBlockText(*want.block) : std::string("none"));
    if (!same(r.mu, want.mu))
        return "mu = " + text(r.mu) + ", the study file says " + text(want.mu);
    if (!same(r.tstar, want.tstar))
        return "tstar = " + text(r.tstar) + ", the study file says " + text(want.tstar);
    if (r.floorPeriod != want.floorPeriod || r.floorDamping != want.floorDamping)
        return "floor filter T = " + text(r.floorPeriod) + " s, zeta = " + text(r.floorDamping) +
               ", the study file says T = " + text(want.floorPeriod) +
               " s, zeta = " + text(want.floorDamping);
    if (r.level != want.level)
        return "level " + text(r.level) + ", the study file says " + text(want.level);
    // Rows name their motion only when the study file lists motions: "record" otherwise.
    if (r.motion.value_or("record") != motionName(c.motion))
        return "motion " + r.motion.value_or("record") + ", the study file says " +
               motionName(c.motion);
    if (r.polarity != want.polarity)
        return "polarity " + r.polarity.value_or("none") + ", the study file says " +
               want.polarity.value_or("none");
    if (!same(r.scale.value_or(1.0), c.record->scale))
        return "record scale " + text(r.scale.value_or(1.0)) + ", the study file says " +
               text(c.record->scale);
    if (!same(r.limit, want.limit))
        return "limit = " + text(r.limit) + ", the study file says " + text(want.limit);
    if (r.measure != want.measure)
        return "measure " + r.measure + ", the study file says " + want.measure;
    if (r.criticalIntensity && r.criticalPeak && *r.criticalIntensity > 0) {
        const double maxG = r.limitIntensity * *r.criticalPeak / *r.criticalIntensity;
        if (!same(maxG, s.search.to, 1e-9))
            return "search up to " + text(maxG) + " g, the study file says " + text(s.search.to);
    }
    return {};
}

} // namespace

std::string studyRowsMismatch(const StudySpec& spec, const std::string& studyDir,
                              const std::vector<StudyRow>& rows) {
    const std::size_t cases = studyCaseCount(spec);
    if (rows.size() != cases)
        return std::to_string(rows.size()) + " rows, the study file has " + std::to_string(cases) +
               " cases";
    if (spec.fingerprint.empty()) throw std::logic_error("studyRowsMismatch: records not hashed");
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (rows[i].index != i)
            return "row " + std::to_string(i + 1) + " is case " + std::to_string(rows[i].index);
        const std::string m = caseMismatch(spec, studyDir, rows[i], studyCase(spec, i));
        if (!m.empty()) return "row " + std::to_string(i + 1) + ": " + m;
    }
    // The same inputs, yet another study: a record's bytes, the search's step or tolerance, or
    // the building differ from what the rows were computed with.
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (rows[i].study != spec.fingerprint)
            return "row " + std::to_string(i + 1) + " is of study " + rows[i].study +
                   ", the study file and its records are study " + spec.fingerprint +
                   " (a record, the search or the building changed)";
    }
    return {};
}

} // namespace kinstab
