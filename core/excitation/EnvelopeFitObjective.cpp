// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/excitation/EnvelopeFitObjective.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace kinstab {

double ratioOf(double z) {
    return z < 0.0 ? 1.0 + z : std::exp(z);
}

double zOfRatio(double r) {
    return r < 1.0 ? r - 1.0 : std::log(r);
}

FitPeaks fitPeaks(const std::vector<PeakPoint>& p, double dt) {
    FitPeaks f;
    f.dt = dt;
    double before = 0.0;
    for (const PeakPoint& q : p) {
        f.time.push_back(q.time);
        f.value.push_back(q.value);
        f.sumSquares += q.value * q.value;
        // halfCyclePeaks times a peak dt * i: the gap is a whole number of samples.
        f.gap.push_back(static_cast<std::uint32_t>(std::lround((q.time - before) / dt)));
        before = q.time;
    }
    return f;
}

namespace {

// Values below 1e-150 count as 0 (exp(-345)): their products with the peaks' other factors would
// be subnormal, which adds nothing to the sums and costs the CPU ~100 cycles each.
double flushed(double v) {
    return v < 1e-150 ? 0.0 : v;
}

// out[2 q + lane] = exp(-rate t_q) as exp(-rate t_{q-1}) exp(-rate dt)^gap_q: the powers of one
// exp(-rate dt) (by multiplication, up to 256) instead of an exp per peak; the relative error
// grows by an ulp a factor, below 1e-12 over any record.
void fillDecays(const FitPeaks& p, double rate, std::vector<double>& out, std::size_t lane) {
    constexpr std::uint32_t kTabled = 256;
    thread_local std::vector<double> powers;
    powers.assign(kTabled + 1, 0.0);
    const double step = std::exp(-rate * p.dt);
    powers[0] = 1.0;
    for (std::uint32_t d = 1; d <= kTabled; ++d)
        powers[d] = flushed(powers[d - 1] * step);
    double v = 1.0;
    for (std::size_t q = 0; q < p.time.size(); ++q) {
        const std::uint32_t g = p.gap[q];
        const double factor =
            g <= kTabled && q > 0 ? powers[g] : std::exp(std::max(-rate * p.dt * g, -700.0));
        v = flushed(v * factor);
        out[2 * q + lane] = v;
    }
}

// e = exp(-alpha t) - exp(-beta t) with w = beta - alpha >= 1e-3 alpha: the difference loses at
// most -log10(1e-3 alpha t) digits, 5 at the first peaks of a slow envelope, 1e-11 of e (and
// nothing of the sums). d = de/dx, de/dz's y-part; dd = the second derivatives (in y = ln r,
// turned to z below). The derivatives are written without the difference where it matters.
// The sums: ee, ep, <e,dx>, <e,dy>, <p,dx>, <p,dy>, <dx,dx>, <dx,dy>, <dy,dy>, <p,dd..>, <e,dd..>
using PeakSums = std::array<double, 15>;

PeakSums peakSums(const FitPeaks& p, double alpha, double w, double beta) {
    const std::size_t n = p.time.size();
    thread_local std::vector<double> decays;
    decays.resize(2 * n);
    fillDecays(p, alpha, decays, 0);
    fillDecays(p, beta, decays, 1);
    // Two peaks at a time into two sets of sums: the compiler pairs their arithmetic.
    double pair[2][15] = {};
    const auto add = [&](std::size_t q, double* acc) {
        const double t = p.time[q], v = p.value[q], a = decays[2 * q], b = decays[2 * q + 1];
        const double e = a - b;
        const double dx = t * (w * b - alpha * e), dy = t * w * b;
        const double dxx = dx + t * t * (alpha * alpha * e - w * (alpha + beta) * b);
        const double dxy = dy * (1.0 - t * beta), dyy = dy * (1.0 - t * w);
        const double terms[15] = {e * e,   e * v,   e * dx,  e * dy,  v * dx,
                                  v * dy,  dx * dx, dx * dy, dy * dy, v * dxx,
                                  v * dxy, v * dyy, e * dxx, e * dxy, e * dyy};
        for (int k = 0; k < 15; ++k)
            acc[k] += terms[k];
    };
    std::size_t q = 0;
    for (; q + 2 <= n; q += 2) {
        add(q, pair[0]);
        add(q + 1, pair[1]);
    }
    if (q < n) add(q, pair[0]);
    PeakSums s{};
    for (int k = 0; k < 15; ++k)
        s[static_cast<std::size_t>(k)] = pair[0][k] + pair[1][k];
    return s;
}

// f_i = -2 c N_i + c^2 D_i with N_i = <p,d_i>, D_i = 2 <e,d_i>; f_ij = -2 (N_i - c D_i)
// (N_j - c D_j) / D + c (c D_ij - 2 N_ij) with D_ij = 2 (<d_i,d_j> + <e,d_ij>); in (x, y).
void gradientAndHessian(const PeakSums& s, double c, FitPoint& r) {
    const double D = s[0];
    const double u[2] = {s[4] - 2.0 * c * s[2], s[5] - 2.0 * c * s[3]};
    r.g = {-2.0 * c * s[4] + 2.0 * c * c * s[2], -2.0 * c * s[5] + 2.0 * c * c * s[3]};
    for (std::size_t k = 0; k < 3; ++k) {
        const std::size_t i = k == 2 ? 1 : 0, j = k == 0 ? 0 : 1;
        const double dij = 2.0 * (s[6 + k] + s[12 + k]);
        r.h[k] = -2.0 * u[i] * u[j] / D + c * (c * dij - 2.0 * s[9 + k]);
    }
}

} // namespace

FitPoint evaluateFit(const FitPeaks& p, double x, double z) {
    const double alpha = std::exp(x), w = alpha * ratioOf(z), beta = alpha + w;
    const PeakSums s = peakSums(p, alpha, w, beta);
    FitPoint r{x, z};
    const double D = s[0], N = s[1];
    if (!(D > 0.0) || !(N > 0.0)) { // no positive envelope fits: f = pp, flat
        r.sse = p.sumSquares;
        return r;
    }
    const double c = N / D;
    r.scale = c;
    r.sse = p.sumSquares - c * N;
    gradientAndHessian(s, c, r);
    if (z < 0.0) { // from y = ln(1 + z): dy/dz = 1 / r, d2y/dz2 = -1 / r^2
        const double inv = 1.0 / ratioOf(z);
        r.h[2] = r.h[2] * inv * inv - r.g[1] * inv * inv;
        r.h[1] *= inv;
        r.g[1] *= inv;
    }
    return r;
}

} // namespace kinstab
