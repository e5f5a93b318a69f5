// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/excitation/EnvelopeFitStart.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kinstab {

namespace {

// The rates' span: from 0.05 / (last peak's time), where exp(-g t) is 1 - g t to 5 % over the
// record, to 20 / (first peak's time), where it is below 3e-9 at every peak, in factors of 4: at
// most 12 rates (a span of 4^11 = 4e6; a wider span loses its top, where the beta -> infinity end
// stands in).
// Beyond either end the pairs differ from the ends' own by less than the grid's step (and the
// refinement's box reaches further).
struct Rates {
    double first = 0;
    int count = 0;
    double at(int k) const { return std::ldexp(first, 2 * k); }
};

Rates ratesFor(const FitPeaks& p) {
    double first = std::numeric_limits<double>::infinity(), last = 0.0;
    for (double t : p.time) {
        if (t > 0.0) first = std::min(first, t);
        last = std::max(last, t);
    }
    const double lo = 0.05 / last, hi = 20.0 / first;
    const int count = static_cast<int>(std::ceil(0.5 * std::log2(hi / lo))) + 1;
    return {lo, std::clamp(count, 2, 12)};
}

// Values below 1e-150 count as 0: they add nothing a sum of peaks (>= 1e-150 g^2 apart from 0)
// can hold, and their squares and products would be subnormal, which costs the CPU ~100 cycles
// each (they were half the grid's time).
double flushed(double v) {
    return v < 1e-150 ? 0.0 : v;
}

// Row k: exp(-g_k t_q). g_{k+1} = 4 g_k, so a row is the one before to the 4th power; each
// squaring doubles the relative error, so row k is within 4^k ulp (< 1e-10 for k < 13), far finer
// than the grid needs; only row 0 calls exp.
std::vector<double> decayRows(const FitPeaks& p, const Rates& r) {
    const std::size_t n = p.time.size();
    std::vector<double> rows(n * static_cast<std::size_t>(r.count));
    for (std::size_t q = 0; q < n; ++q)
        rows[q] = flushed(std::exp(std::max(-r.at(0) * p.time[q], -700.0)));
    for (int k = 1; k < r.count; ++k) {
        double* row = rows.data() + n * static_cast<std::size_t>(k);
        const double* before = row - n;
        for (std::size_t q = 0; q < n; ++q) {
            const double square = flushed(before[q] * before[q]);
            row[q] = flushed(square * square);
        }
    }
    return rows;
}

double dot(const double* a, const double* b, std::size_t n) {
    double s = 0.0;
    for (std::size_t q = 0; q < n; ++q)
        s += a[q] * b[q];
    return s;
}

// out[j] = <a, b_j> for rows b_j = b + j n, j < 4: four sums at once share the loads of a and
// run in parallel (a single sum waits on its own additions).
void dot4(const double* a, const double* b, std::size_t n, double* out) {
    double s0 = 0.0, s1 = 0.0, s2 = 0.0, s3 = 0.0;
    const double *b1 = b + n, *b2 = b1 + n, *b3 = b2 + n;
    for (std::size_t q = 0; q < n; ++q) {
        s0 += a[q] * b[q];
        s1 += a[q] * b1[q];
        s2 += a[q] * b2[q];
        s3 += a[q] * b3[q];
    }
    out[0] = s0, out[1] = s1, out[2] = s2, out[3] = s3;
}

// min_c |p - c e|^2 from <e,e> and <e,p>: pp when no positive c fits.
double projectedSse(double ee, double ep, double pp) {
    return ee > 0.0 && ep > 0.0 ? pp - ep * ep / ee : pp;
}

void keep(EnvelopeStart& best, double sse, double x, double z) {
    if (sse < best.sse) best = {x, z, sse};
}

// The columns (rates alpha) whose best is below both neighbours', best first, at most `count`,
// each within 25 % of the best's SSE.
std::vector<EnvelopeStart> localMinima(const std::vector<EnvelopeStart>& column,
                                       std::size_t count) {
    std::vector<EnvelopeStart> out;
    for (std::size_t k = 0; k < column.size(); ++k) {
        const bool belowLeft = k == 0 || column[k].sse <= column[k - 1].sse;
        const bool belowRight = k + 1 == column.size() || column[k].sse < column[k + 1].sse;
        if (belowLeft && belowRight) out.push_back(column[k]);
    }
    std::sort(out.begin(), out.end(),
              [](const EnvelopeStart& a, const EnvelopeStart& b) { return a.sse < b.sse; });
    // Another valley is worth a refinement only when its grid point comes near the best's.
    while (out.size() > count || (out.size() > 1 && out.back().sse > 1.25 * out.front().sse))
        out.pop_back();
    return out;
}

} // namespace

std::vector<EnvelopeStart> envelopeStarts(const FitPeaks& p, std::size_t starts) {
    const Rates r = ratesFor(p);
    const std::size_t n = p.time.size(), count = static_cast<std::size_t>(r.count);
    const double pp = p.sumSquares;
    const std::vector<double> rows = decayRows(p, r);
    const auto row = [&](std::size_t k) { return rows.data() + n * k; };
    const std::vector<double>& value = p.value;
    std::vector<double> timed(n), gram(count * count), projection(count);
    for (std::size_t k = 0; k < count; ++k) {
        projection[k] = dot(row(k), value.data(), n);
        std::size_t l = k;
        for (; l + 4 <= count; l += 4)
            dot4(row(k), row(l), n, &gram[k * count + l]);
        for (; l < count; ++l)
            gram[k * count + l] = dot(row(k), row(l), n);
    }
    std::vector<EnvelopeStart> column(count);
    const double zNear = zOfRatio(0.05), lnFar = std::log(r.at(r.count));
    for (std::size_t k = 0; k < count; ++k) {
        EnvelopeStart& best = column[k];
        best.sse = std::numeric_limits<double>::infinity();
        const double x = std::log(r.at(static_cast<int>(k)));
        for (std::size_t l = k + 1; l < count; ++l) {
            const double ee = gram[k * count + k] - 2.0 * gram[k * count + l] + gram[l * count + l];
            keep(best, projectedSse(ee, projection[k] - projection[l], pp), x,
                 zOfRatio(std::ldexp(1.0, 2 * static_cast<int>(l - k)) - 1.0));
        }
        // The valley's ends: beta -> alpha (e / (beta - alpha) -> t exp(-alpha t)) and beta -> inf.
        for (std::size_t q = 0; q < n; ++q)
            timed[q] = p.time[q] * row(k)[q];
        keep(best,
             projectedSse(dot(timed.data(), timed.data(), n), dot(timed.data(), value.data(), n),
                          pp),
             x, zNear);
        keep(best, projectedSse(gram[k * count + k], projection[k], pp), x, lnFar - x);
    }
    return localMinima(column, starts);
}

} // namespace kinstab
