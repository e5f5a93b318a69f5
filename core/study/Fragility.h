// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Collapse fragility per parameter set of a study (docs/studies.md): the lognormal fit to the
// records' critical intensities (censored where a record never collapses), confidence bounds by
// a seeded bootstrap over the records, and the empirical points (Kaplan-Meier, censored records
// at their limit intensities).

#include "core/study/LognormalFit.h"
#include "core/study/StudyRow.h"
#include "core/study/StudySpec.h"

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
    // Threads of core's pool (core/sweep/ParallelFor.h) the resamples' fits run on; <= 0: all
    // hardware threads. The bounds are the same bits whatever the count.
    int threads = 0;
};

// Records drawn by one set's bootstrap (resamples x records), each a term of a likelihood fit.
// Measured on the 2-core CI machine (scripts/fragility-rows.py): about 0.15 us of one core per
// draw of a collapsing record, 4 us per draw of a censored one (its term is an erfc), so one set
// takes at most about 1.5 s of one core, 20 s with half its records censored, 40 s with nearly
// all. Ten million is the default 1000 resamples of the largest suite a study holds
// (kMaxStudyRecords records); a set of more rows is no study's.
inline constexpr std::size_t kMaxBootstrapDraws = 1000 * kMaxStudyRecords;
// Empty when the bootstrap of a set of `records` records is within kMaxBootstrapDraws; else
// "1000 resamples x 20000 records of the set = 2e+07 draws, more than the limit of 1e+07: at
// most 500 resamples (or 0)".
std::string bootstrapWorkError(std::size_t records, const BootstrapSettings& b);

// rows: one parameter set's rows (any order). Deterministic for a given seed, whatever
// b.threads. Throws StudyError (bootstrapWorkError) when the bootstrap exceeds its bound.
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
