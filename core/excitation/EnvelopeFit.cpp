// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/excitation/EnvelopeFit.h"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace kinstab {

double EnvelopeFit::at(double t) const {
    return scale * (std::exp(-alpha * t) - std::exp(-beta * t));
}

std::vector<PeakPoint> halfCyclePeaks(const Accelerogram& motion) {
    std::vector<PeakPoint> peaks;
    PeakPoint best;
    int sign = 0;
    for (std::size_t i = 0; i < motion.samples.size(); ++i) {
        const double a = motion.samples[i];
        const int s = (a > 0.0) - (a < 0.0);
        if (s != 0 && s != sign) {
            if (sign != 0) peaks.push_back(best);
            sign = s;
            best = {};
        }
        if (std::abs(a) > best.value) best = {motion.dt * static_cast<double>(i), std::abs(a)};
    }
    if (best.value > 0.0) peaks.push_back(best);
    return peaks;
}

namespace {

struct Trial {
    double alpha, beta, scale, sse;
};

// exp(x) is exactly +0 below this (the smallest subnormal is exp(-745.13...)): skipping the call
// there changes no bit of the sums.
constexpr double kExpUnderflow = -746.0;

double expOrZero(double x) {
    return x < kExpUnderflow ? 0.0 : std::exp(x);
}

// For fixed alpha, beta the best c is linear least squares. decayAlpha[q] = exp(-alpha t_q), formed
// once per alpha of the grid (21 per round instead of 441): the same values, so the same sums.
Trial evaluate(const std::vector<PeakPoint>& p, const std::vector<double>& decayAlpha, double alpha,
               double beta) {
    double ee = 0.0, ep = 0.0, pp = 0.0;
    for (std::size_t k = 0; k < p.size(); ++k) {
        const PeakPoint& q = p[k];
        const double e = decayAlpha[k] - expOrZero(-beta * q.time);
        ee += e * e;
        ep += e * q.value;
        pp += q.value * q.value;
    }
    const double c = ee > 0.0 ? std::max(0.0, ep / ee) : 0.0;
    return {alpha, beta, c, pp - 2.0 * c * ep + c * c * ee};
}

// Grid over (ln alpha, ln(beta/alpha - 1)), then zoom in around the best point: the objective
// is smooth but has long curved valleys, so a shrinking grid is more robust than Newton here.
Trial search(const std::vector<PeakPoint>& p) {
    Trial best{0, 0, 0, std::numeric_limits<double>::infinity()};
    double cx = std::log(0.1), cy = std::log(2.0), span = 7.0;
    std::vector<double> decayAlpha(p.size());
    for (int round = 0; round < 12; ++round) {
        const double x0 = cx, y0 = cy;
        for (int i = -10; i <= 10; ++i) {
            const double x = x0 + span * i / 10.0;
            const double alpha = std::exp(x);
            if (alpha > 1e3) continue; // every beta of this row is skipped below
            for (std::size_t k = 0; k < p.size(); ++k)
                decayAlpha[k] = expOrZero(-alpha * p[k].time);
            for (int j = -10; j <= 10; ++j) {
                const double y = y0 + span * j / 10.0;
                const double beta = alpha * (1.0 + std::exp(y));
                if (!std::isfinite(beta) || beta > 1e4) continue;
                const Trial t = evaluate(p, decayAlpha, alpha, beta);
                if (t.sse < best.sse) {
                    best = t;
                    cx = x;
                    cy = y;
                }
            }
        }
        span *= 0.4;
    }
    return best;
}

} // namespace

EnvelopeFit fitEnvelope(const Accelerogram& motion) {
    const std::vector<PeakPoint> p = halfCyclePeaks(motion);
    if (p.size() < 3)
        throw std::invalid_argument("the motion has " + std::to_string(p.size()) +
                                    " half-cycle peaks: at least 3 are needed to fit an envelope");
    const Trial t = search(p);
    return {t.alpha, t.beta, t.scale,
            std::sqrt(std::max(0.0, t.sse) / static_cast<double>(p.size())), p.size()};
}

} // namespace kinstab
