// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One case's result: its inputs and the intensity at which the scaled record first collapses the
// slab, or none up to the search limit (then the record is censored at the limit's intensity).
// A value: its JSONL line is written and read by core/io/StudyRowJson.h, a floor above.

#include "core/study/StudyBlock.h"

#include <cstddef>
#include <optional>
#include <string>

namespace kinstab {

struct StudyRow {
    std::size_t index = 0, cases = 0, set = 0;
    std::string study;  // the study's fingerprint (core/study/StudyFingerprint.h)
    std::string record; // label: the path relative to the study file
    double mu = 0, tstar = 0, limit = 0;
    std::optional<double> floorPeriod, floorDamping;
    std::string measure;                     // intensityName(), e.g. "pga"
    double recordIntensity = 0;              // g, the unscaled record's intensity measure
    std::optional<double> criticalIntensity; // g; none: no collapse up to the limit
    std::optional<double> criticalPeak;      // g, peak of the driving motion at collapse
    double limitIntensity = 0;               // g, the intensity at the search limit
    long runs = 0;
    // Written only when the study uses them, so that older studies keep their bytes:
    std::optional<int> level;            // the level of the study's building that drives the slab
    std::optional<std::string> motion;   // "record" or "fitted_sine" (its enveloped-sine surrogate)
    std::optional<std::string> polarity; // "normal" or "inverted": the study runs both
    std::string noFit;                   // fitted_sine: why the motion has no envelope fit
    std::optional<double> scale;         // the record's scale in the suite; then also:
    double imAsGiven = 0;                // g, scale x recordIntensity
    bool collapsesAsGiven = false;       // criticalIntensity <= imAsGiven
    std::optional<double> margin;        // criticalIntensity / imAsGiven
    // A block study's rows: the block instead of mu, tstar and limit (0 then), and whether its
    // search stopped at its run limit (written only when it did).
    std::optional<StudyBlock> block;
    bool runLimitReached = false;
    bool operator==(const StudyRow&) const = default;
};

// What drives the slab in words, for tables and legends: "ground", "floor T = 1 s, ζ = 0.02" or
// "level 8", with ", fitted sine" when the case runs the motion's enveloped-sine surrogate.
// (A row's polarity is the record's, not the set's: recordText says it.)
std::string studyDriverText(const StudyRow& r);
// The record a row ran: its label, with " (inverted)" for the inverted polarity.
std::string studyRecordText(const StudyRow& r);

} // namespace kinstab
