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
    double intensity = 0;               // g
    double probability = 0;             // of the fit
    std::optional<double> lower, upper; // pointwise bootstrap bounds; none without a bootstrap
};

// What SLAMMER-style record-suite summaries give beside a fitted fragility: the spread of the
// critical intensity over the records that collapse (the censored ones have none, and are
// counted). Standard deviations with divisor n - 1 (none below two collapses).
struct RecordStatistics {
    std::size_t collapsed = 0, censored = 0;
    std::optional<double> meanG, medianG, stdG; // of the critical intensities, g
    std::optional<double> meanLn, stdLn;        // of their natural logarithms (ln g)
};

struct Fragility {
    StudyRow parameters; // the set's first row: mu, t*, floor, measure
    std::size_t records = 0, collapsed = 0;
    std::size_t withoutFit = 0; // fitted_sine rows whose motion has no envelope fit: left out
    std::optional<double> collapsedAsGiven; // fraction of the records that collapse as given
    std::optional<LognormalFit> fit;
    std::string noFit; // why there is no fit
    // The fit's median lies above every record's search limit: an extrapolation beyond the
    // intensities searched (searchTop), not a finding.
    bool medianBeyondSearch = false;
    double searchTop = 0;     // g, the largest limit intensity of the set's records
    bool betaAtBound = false; // the fit's beta is at the search's bound (LognormalFit.h)
    // Bootstrap bounds: percentiles over the resamples, widened to contain the estimate. A
    // resample that cannot be fitted (fewer than two distinct collapses) is one whose median lies
    // beyond what it shows: it counts as an infinite median (and probability 0 on the curve),
    // so medianUpper may be infinite; beta's bounds are over the fitted resamples only.
    std::optional<double> medianLower, medianUpper, betaLower, betaUpper;
    std::size_t resamples = 0, fitted = 0; // bootstrap resamples asked for and fitted
    std::vector<FragilityPoint> points;
    std::vector<FragilityCurvePoint> curve;
    RecordStatistics statistics;
};

struct BootstrapSettings {
    std::size_t resamples = 1000;
    unsigned long long seed = 1;
    double level = 0.90; // two-sided confidence level of the bounds
};

// rows: one parameter set's rows (any order). Deterministic for a given seed.
Fragility fragilityOf(const std::vector<StudyRow>& rows, const BootstrapSettings& b);
// The bootstrap's resampled fits in resample order, none where a resample cannot be fitted: the
// resamples whose percentiles are fragilityOf's bounds (the same rows, seed and order), for what
// is computed from each fit (core/risk). Empty when no row has an envelope fit.
std::vector<std::optional<LognormalFit>> fragilityResamples(const std::vector<StudyRow>& rows,
                                                            const BootstrapSettings& b);
// Groups rows by parameter set, in set order.
std::vector<Fragility> studyFragility(const std::vector<StudyRow>& rows,
                                      const BootstrapSettings& b);

} // namespace kinstab
