// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/Fragility.h"

#include "core/study/KaplanMeier.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

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

// The q-quantile of sorted values, linear between order statistics.
double quantile(const std::vector<double>& sorted, double q) {
    const double pos = q * static_cast<double>(sorted.size() - 1);
    const auto i = static_cast<std::size_t>(std::floor(pos));
    const std::size_t j = std::min(i + 1, sorted.size() - 1);
    return sorted[i] + (pos - static_cast<double>(i)) * (sorted[j] - sorted[i]);
}

std::vector<LognormalFit> bootstrapFits(const std::vector<const StudyRow*>& rows,
                                        const BootstrapSettings& b) {
    // mt19937_64 is specified to the bit by the C++ standard, and the index is taken from its
    // output by arithmetic alone (not by a library distribution), so every platform resamples
    // the same records.
    std::mt19937_64 rng(b.seed);
    std::vector<LognormalFit> fits;
    std::vector<const StudyRow*> pick(rows.size());
    for (std::size_t k = 0; k < b.resamples; ++k) {
        for (auto& p : pick)
            p = rows[rng() % rows.size()];
        if (auto f = fitLognormal(sampleOf(pick))) fits.push_back(*f);
    }
    return fits;
}

void addBounds(Fragility& f, const std::vector<LognormalFit>& fits, double level) {
    const double lo = 0.5 * (1.0 - level), hi = 1.0 - lo;
    std::vector<double> medians, betas;
    for (const auto& x : fits) {
        medians.push_back(x.median);
        betas.push_back(x.beta);
    }
    std::sort(medians.begin(), medians.end());
    std::sort(betas.begin(), betas.end());
    f.medianLower = quantile(medians, lo);
    f.medianUpper = quantile(medians, hi);
    f.betaLower = quantile(betas, lo);
    f.betaUpper = quantile(betas, hi);
    std::vector<double> p(fits.size());
    for (FragilityCurvePoint& c : f.curve) {
        for (std::size_t k = 0; k < fits.size(); ++k)
            p[k] = lognormalCdf(c.intensity, fits[k].median, fits[k].beta);
        std::sort(p.begin(), p.end());
        c.lower = quantile(p, lo);
        c.upper = quantile(p, hi);
    }
}

// Each collapsing record at its critical intensity with the Kaplan-Meier probability there
// (records that never collapse are censored at their limit intensities).
std::vector<FragilityPoint> empiricalPoints(const std::vector<const StudyRow*>& rows) {
    std::vector<FragilityPoint> points;
    for (const StudyRow* r : rows)
        if (r->criticalIntensity) points.push_back({r->record, *r->criticalIntensity, 0.0});
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

} // namespace

Fragility fragilityOf(const std::vector<StudyRow>& rows, const BootstrapSettings& b) {
    std::vector<const StudyRow*> ptrs;
    Fragility f;
    // A fitted_sine row without a fit is no record surviving the search: it is left out.
    for (const StudyRow& r : rows)
        if (r.noFit.empty())
            ptrs.push_back(&r);
        else
            ++f.withoutFit;
    std::sort(ptrs.begin(), ptrs.end(), [](auto* x, auto* y) { return x->index < y->index; });
    if (ptrs.empty()) {
        if (!rows.empty()) f.parameters = rows.front();
        f.noFit = "no record has an envelope fit";
        return f;
    }
    f.parameters = *ptrs.front();
    f.records = ptrs.size();
    if (f.parameters.scale) {
        const auto given = std::count_if(ptrs.begin(), ptrs.end(),
                                         [](const StudyRow* r) { return r->collapsesAsGiven; });
        f.collapsedAsGiven = static_cast<double>(given) / static_cast<double>(ptrs.size());
    }
    f.points = empiricalPoints(ptrs);
    f.collapsed = f.points.size();
    f.fit = fitLognormal(sampleOf(ptrs), &f.noFit);
    f.resamples = b.resamples;
    if (!f.fit) return f;
    double top = 0.0; // the curve spans up to the largest limit or collapse intensity
    for (const StudyRow* r : ptrs)
        top = std::max({top, r->limitIntensity, r->criticalIntensity.value_or(0.0)});
    for (int i = 1; i <= kCurvePoints; ++i) {
        const double x = top * i / kCurvePoints;
        f.curve.push_back({x, lognormalCdf(x, f.fit->median, f.fit->beta), 0.0, 0.0});
    }
    const std::vector<LognormalFit> fits = bootstrapFits(ptrs, b);
    f.fitted = fits.size();
    if (!fits.empty()) addBounds(f, fits, b.level);
    return f;
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
