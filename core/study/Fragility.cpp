// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/Fragility.h"

#include "core/base/TextInput.h"
#include "core/numerics/Quantile.h"
#include "core/study/KaplanMeier.h"
#include "core/sweep/ParallelFor.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <tuple>

namespace kinstab {

namespace {

CensoredSample sampleOf(const std::vector<const StudyRow*>& rows) {
    CensoredSample s;
    for (const StudyRow* r : rows) {
        if (r->criticalIntensity)
            s.collapsed.push_back(*r->criticalIntensity);
        else
            s.censored.push_back(r->limitIntensity);
    }
    return s;
}

// Resamples whose draws come from one saved state of the stream, fitted one after another on one
// thread: a fixed count, so that the chunks, and with them the resamples, do not depend on the
// number of threads; 256 states of mt19937_64 are 640 kB.
constexpr std::size_t kBootstrapChunks = 256;

// One fit per resample; none where the resample cannot be fitted.
std::vector<std::optional<LognormalFit>> bootstrapFits(const std::vector<const StudyRow*>& rows,
                                                       const BootstrapSettings& b) {
    // mt19937_64 is specified to the bit by the C++ standard, and the index is taken from its
    // output by arithmetic alone (not by a library distribution), so every platform resamples
    // the same records. Resample k takes the k-th block of rows.size() outputs of the one stream,
    // as a plain loop would: the state at each chunk's first block is saved in one pass of
    // draws (nanoseconds each, against a fit's microseconds), then the chunks run in parallel.
    const std::size_t n = rows.size();
    const std::size_t perChunk = (b.resamples + kBootstrapChunks - 1) / kBootstrapChunks;
    std::vector<std::mt19937_64> starts;
    std::mt19937_64 rng(b.seed);
    for (std::size_t k = 0; k < b.resamples; k += perChunk) {
        starts.push_back(rng);
        rng.discard(static_cast<unsigned long long>(n) * std::min(perChunk, b.resamples - k));
    }
    std::vector<std::optional<LognormalFit>> fits(b.resamples);
    parallelFor(starts.size(), b.threads, nullptr, [&](std::size_t c) {
        std::mt19937_64 draw = starts[c];
        std::vector<const StudyRow*> pick(n);
        for (std::size_t k = c * perChunk; k < std::min((c + 1) * perChunk, b.resamples); ++k) {
            for (auto& p : pick)
                p = rows[draw() % n];
            fits[k] = fitLognormal(sampleOf(pick));
        }
    });
    return fits;
}

// The quantile interval [lo, hi] of the values, widened to contain the estimate.
std::pair<double, double> interval(std::vector<double> v, double lo, double hi, double estimate) {
    std::sort(v.begin(), v.end());
    return {std::min(quantile(v, lo), estimate), std::max(quantile(v, hi), estimate)};
}

void addBounds(Fragility& f, const std::vector<std::optional<LognormalFit>>& fits, double level) {
    const double lo = 0.5 * (1.0 - level), hi = 1.0 - lo;
    constexpr double inf = std::numeric_limits<double>::infinity();
    std::vector<double> medians, betas;
    for (const auto& x : fits) {
        medians.push_back(x ? x->median : inf); // unfitted: too few collapses to show a median
        if (x) betas.push_back(x->beta);
    }
    std::tie(f.medianLower, f.medianUpper) = interval(medians, lo, hi, f.fit->median);
    if (!betas.empty()) std::tie(f.betaLower, f.betaUpper) = interval(betas, lo, hi, f.fit->beta);
    std::vector<double> p(fits.size());
    for (FragilityCurvePoint& c : f.curve) {
        for (std::size_t k = 0; k < fits.size(); ++k)
            p[k] = fits[k] ? lognormalCdf(c.intensity, fits[k]->median, fits[k]->beta) : 0.0;
        std::tie(c.lower, c.upper) = interval(p, lo, hi, c.probability);
    }
}

// Each collapsing record at its critical intensity with the Kaplan-Meier probability there
// (records that never collapse are censored at their limit intensities).
std::vector<FragilityPoint> empiricalPoints(const std::vector<const StudyRow*>& rows) {
    std::vector<FragilityPoint> points;
    for (const StudyRow* r : rows)
        if (r->criticalIntensity)
            points.push_back({studyRecordText(*r), *r->criticalIntensity, 0.0});
    std::stable_sort(points.begin(), points.end(),
                     [](const auto& a, const auto& b) { return a.intensity < b.intensity; });
    const std::vector<KaplanMeierStep> steps = kaplanMeier(sampleOf(rows));
    std::size_t k = 0;
    for (FragilityPoint& p : points) {
        while (steps[k].intensity < p.intensity)
            ++k;
        p.probability = steps[k].probability;
    }
    return points;
}

constexpr int kCurvePoints = 41;

// Mean and standard deviation (divisor n - 1) of v, not empty.
std::pair<double, std::optional<double>> meanAndDeviation(const std::vector<double>& v) {
    double mean = 0.0;
    for (double x : v)
        mean += x / static_cast<double>(v.size());
    if (v.size() < 2) return {mean, std::nullopt};
    double sum = 0.0;
    for (double x : v)
        sum += (x - mean) * (x - mean);
    return {mean, std::sqrt(sum / static_cast<double>(v.size() - 1))};
}

RecordStatistics recordStatistics(const std::vector<const StudyRow*>& rows) {
    RecordStatistics s;
    std::vector<double> x, ln;
    for (const StudyRow* r : rows)
        if (r->criticalIntensity && *r->criticalIntensity > 0.0) {
            x.push_back(*r->criticalIntensity);
            ln.push_back(std::log(*r->criticalIntensity));
        }
    s.collapsed = x.size();
    s.censored = rows.size() - x.size();
    if (x.empty()) return s;
    std::tie(s.meanG, s.stdG) = meanAndDeviation(x);
    std::tie(s.meanLn, s.stdLn) = meanAndDeviation(ln);
    std::sort(x.begin(), x.end());
    s.medianG = quantile(x, 0.5);
    return s;
}

// The rows the fit and the bootstrap use, in case order: a fitted_sine row without a fit is no
// record surviving the search, so it is left out.
std::vector<const StudyRow*> fittedRows(const std::vector<StudyRow>& rows) {
    std::vector<const StudyRow*> ptrs;
    for (const StudyRow& r : rows)
        if (r.noFit.empty()) ptrs.push_back(&r);
    std::sort(ptrs.begin(), ptrs.end(), [](auto* x, auto* y) { return x->index < y->index; });
    return ptrs;
}

} // namespace

std::string bootstrapWorkError(std::size_t records, const BootstrapSettings& b) {
    if (records == 0 || b.resamples <= kMaxBootstrapDraws / records) return {};
    return std::to_string(b.resamples) + " resamples x " + std::to_string(records) +
           " records of the set = " +
           formatDouble(static_cast<double>(b.resamples) * static_cast<double>(records)) +
           " draws, more than the limit of " + formatDouble(kMaxBootstrapDraws) + ": at most " +
           std::to_string(kMaxBootstrapDraws / records) + " resamples (or 0)";
}

Fragility fragilityOf(const std::vector<StudyRow>& rows, const BootstrapSettings& b) {
    const std::vector<const StudyRow*> ptrs = fittedRows(rows);
    Fragility f;
    f.withoutFit = rows.size() - ptrs.size();
    if (ptrs.empty()) {
        if (!rows.empty()) f.parameters = rows.front();
        f.noFit = "no record has an envelope fit";
        return f;
    }
    f.parameters = *ptrs.front();
    f.records = ptrs.size();
    if (const std::string e = bootstrapWorkError(f.records, b); !e.empty()) throw StudyError(e);
    if (f.parameters.scale) {
        const auto given = std::count_if(ptrs.begin(), ptrs.end(),
                                         [](const StudyRow* r) { return r->collapsesAsGiven; });
        f.collapsedAsGiven = static_cast<double>(given) / static_cast<double>(ptrs.size());
    }
    f.points = empiricalPoints(ptrs);
    f.collapsed = f.points.size();
    f.statistics = recordStatistics(ptrs);
    f.fit = fitLognormal(sampleOf(ptrs), &f.noFit);
    f.resamples = b.resamples;
    if (!f.fit) return f;
    double top = 0.0; // the curve spans up to the largest limit or collapse intensity
    for (const StudyRow* r : ptrs) {
        top = std::max({top, r->limitIntensity, r->criticalIntensity.value_or(0.0)});
        f.searchTop = std::max(f.searchTop, r->limitIntensity);
    }
    f.medianBeyondSearch = f.fit->median > f.searchTop;
    f.betaAtBound = betaAtBound(f.fit->beta);
    for (int i = 1; i <= kCurvePoints; ++i) {
        const double x = top * i / kCurvePoints;
        f.curve.push_back({x, lognormalCdf(x, f.fit->median, f.fit->beta), {}, {}});
    }
    const std::vector<std::optional<LognormalFit>> fits = bootstrapFits(ptrs, b);
    f.fitted = static_cast<std::size_t>(
        std::count_if(fits.begin(), fits.end(), [](const auto& x) { return x.has_value(); }));
    if (!fits.empty()) addBounds(f, fits, b.level);
    return f;
}

std::vector<std::optional<LognormalFit>> fragilityResamples(const std::vector<StudyRow>& rows,
                                                            const BootstrapSettings& b) {
    const std::vector<const StudyRow*> ptrs = fittedRows(rows);
    if (ptrs.empty()) return {};
    return bootstrapFits(ptrs, b);
}

std::vector<Fragility> studyFragility(const std::vector<StudyRow>& rows,
                                      const BootstrapSettings& b) {
    std::map<std::size_t, std::vector<StudyRow>> sets;
    for (const StudyRow& r : rows)
        sets[r.set].push_back(r);
    std::vector<Fragility> out;
    for (const auto& [set, members] : sets)
        out.push_back(fragilityOf(members, b));
    return out;
}

} // namespace kinstab
