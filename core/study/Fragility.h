// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Collapse fragility per parameter set of a study (docs/studies.md): the lognormal fit to the
// records' critical intensities (censored where a record never collapses), confidence bounds by
// a seeded bootstrap over the records, and the empirical points (Kaplan-Meier, censored records
// at their limit intensities).

#include "core/study/LognormalFit.h"
#include "core/study/StudyRow.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace kinstab {

struct FragilityPoint {
    std::string record;
    double intensity = 0;   // g, the record's critical intensity
    double probability = 0; // Kaplan-Meier estimate at the intensity (core/study/KaplanMeier.h)
};

struct FragilityCurvePoint {
    double intensity = 0;        // g
    double probability = 0;      // of the fit
    double lower = 0, upper = 0; // pointwise bootstrap bounds
};

struct Fragility {
    StudyRow parameters; // the set's first row: mu, t*, floor, measure
    std::size_t records = 0, collapsed = 0;
    std::size_t withoutFit = 0; // fitted_sine rows whose motion has no envelope fit: left out
    std::optional<double> collapsedAsGiven; // fraction of the records that collapse as given
    std::optional<LognormalFit> fit;
    std::string noFit; // why there is no fit
    double medianLower = 0, medianUpper = 0, betaLower = 0, betaUpper = 0;
    std::size_t resamples = 0, fitted = 0; // bootstrap resamples asked for and fitted
    std::vector<FragilityPoint> points;
    std::vector<FragilityCurvePoint> curve;
};

struct BootstrapSettings {
    std::size_t resamples = 1000;
    unsigned long long seed = 1;
    double level = 0.90; // two-sided confidence level of the bounds
};

// rows: one parameter set's rows (any order). Deterministic for a given seed.
Fragility fragilityOf(const std::vector<StudyRow>& rows, const BootstrapSettings& b);
// Groups rows by parameter set, in set order.
std::vector<Fragility> studyFragility(const std::vector<StudyRow>& rows,
                                      const BootstrapSettings& b);

} // namespace kinstab
