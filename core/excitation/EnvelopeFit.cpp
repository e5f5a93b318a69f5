// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/excitation/EnvelopeFit.h"

#include "core/excitation/EnvelopeFitObjective.h"
#include "core/excitation/EnvelopeFitStart.h"

#include <algorithm>
#include <array>
#include <atomic>
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

// The search's box (docs/theory.md §7): alpha in [1e-7, 1e3] 1/s, beta <= 1e4 1/s (the old grid
// search's reach), beta / alpha - 1 >= 1e-3. Many motions' optimum lies at beta -> alpha, where e
// tends to (beta - alpha) t exp(-alpha t); the enveloped sine forms e as a difference of two
// exponentials, so the bound keeps its cancellation below 1e-13 (and the shape within 0.1 %).
const double kMinX = std::log(1e-7), kMaxX = std::log(1e3);
constexpr double kMinRatio = 1e-3, kMaxBeta = 1e4;

constexpr double kMinZ = kMinRatio - 1.0;
double maxZ(double x) {
    return std::log(kMaxBeta / std::exp(x) - 1.0); // > 0: alpha <= 1e3
}

struct Box {
    double lo[2], hi[2];
};

Box boxAt(double x) {
    return {{kMinX, kMinZ}, {kMaxX, maxZ(x)}};
}

bool atBound(const FitPoint& p, int i, double direction) {
    const Box b = boxAt(p.x);
    const double at = i == 0 ? p.x : p.z;
    return (at <= b.lo[i] && direction < 0.0) || (at >= b.hi[i] && direction > 0.0);
}

// The damped Newton step (H + lambda diag H) d = -g on the free coordinates (Marquardt's
// scaling: z's curvature is orders below x's along the valley); lambda grows until the matrix
// is positive definite, so that d descends.
std::array<double, 2> dampedStep(const FitPoint& p, double& lambda, std::array<bool, 2> free) {
    // lambda: the trust's damping in, the damping used out
    const double floor = 1e-12 * (std::abs(p.h[0]) + std::abs(p.h[2])) + 1e-300;
    const double sx = std::max(std::abs(p.h[0]), floor), sy = std::max(std::abs(p.h[2]), floor);
    for (int k = 0; k < 200; ++k) {
        const double a = p.h[0] + lambda * sx, c = p.h[2] + lambda * sy;
        if (!free[0] || !free[1]) {
            if (!free[0] && !free[1]) return {0.0, 0.0};
            const double curvature = free[0] ? a : c;
            if (curvature > 0.0) return {free[0] ? -p.g[0] / a : 0.0, free[1] ? -p.g[1] / c : 0.0};
        } else {
            const double b = p.h[1], det = a * c - b * b;
            if (a > 0.0 && det > 1e-14 * a * c)
                return {-(c * p.g[0] - b * p.g[1]) / det, -(a * p.g[1] - b * p.g[0]) / det};
        }
        lambda = std::max(4.0 * lambda, 1e-6);
    }
    return {0.0, 0.0};
}

// A coordinate at its bound stays there when the descent or the step points out of the box
// (active set); the others take the Newton step of the reduced problem.
std::array<double, 2> newtonStep(const FitPoint& p, double& lambda) {
    std::array<bool, 2> free = {!atBound(p, 0, -p.g[0]), !atBound(p, 1, -p.g[1])};
    const double trust = lambda;
    std::array<double, 2> d = dampedStep(p, lambda, free);
    bool changed = false;
    for (int i = 0; i < 2; ++i) {
        const auto k = static_cast<std::size_t>(i);
        if (free[k] && atBound(p, i, d[k])) free[k] = false, changed = true;
    }
    if (!changed) return d;
    lambda = trust;
    return dampedStep(p, lambda, free);
}

// cur + d, at most 1.5 in either coordinate; a step leaving the box is shortened to its edge
// (direction kept, so it still descends) and lands on the edge exactly.
std::array<double, 2> stepInBox(const FitPoint& cur, std::array<double, 2> d) {
    const double big = std::max(std::abs(d[0]), std::abs(d[1]));
    if (big > 1.5) d = {d[0] * 1.5 / big, d[1] * 1.5 / big};
    const Box box = boxAt(cur.x);
    const double at[2] = {cur.x, cur.z};
    double length = 1.0;
    int edge = -1;
    double edgeValue = 0.0;
    for (int i = 0; i < 2; ++i) {
        const double di = d[static_cast<std::size_t>(i)];
        const double bound = at[i] + di < box.lo[i] ? box.lo[i] : box.hi[i];
        if ((at[i] + di < box.lo[i] || at[i] + di > box.hi[i]) && (bound - at[i]) / di < length)
            length = (bound - at[i]) / di, edge = i, edgeValue = bound;
    }
    std::array<double, 2> to = {cur.x + length * d[0], cur.z + length * d[1]};
    if (edge >= 0) to[static_cast<std::size_t>(edge)] = edgeValue;
    to[0] = std::clamp(to[0], kMinX, kMaxX);
    to[1] = std::clamp(to[1], kMinZ, maxZ(to[0]));
    return to;
}

// Levenberg-Marquardt-damped Newton from the start, kept in the box; a step is taken only when
// it lowers f, so the result is never worse than the start. Ends when an undamped Newton step is
// below 1e-5 (quadratic convergence leaves ~1e-10 in x and z, ~1e-20 of f after it), or when no
// step longer than 1e-10 descends.
FitPoint refine(const FitPeaks& p, FitPoint cur) {
    double trust = 0.0; // damping after rejected steps
    for (int it = 0; it < 60; ++it) {
        double lambda = trust; // raised further where H is not positive definite
        const std::array<double, 2> to = stepInBox(cur, newtonStep(cur, lambda));
        const double moved = std::max(std::abs(to[0] - cur.x), std::abs(to[1] - cur.z));
        if (!(moved > 1e-10)) break; // nothing left to gain at double precision
        const bool undamped = lambda < 1e-6;
        const FitPoint next = evaluateFit(p, to[0], to[1]);
        if (next.sse < cur.sse) {
            cur = next;
            trust = 0.0;
            if (undamped && moved < 1e-5) break;
        } else {
            if (undamped && moved < 1e-5) break;
            trust = std::max(4.0 * trust, 1e-4);
        }
    }
    return cur;
}

} // namespace

namespace {
std::atomic<long> fitsBegun{0};
} // namespace

long envelopeFitsBegun() {
    return fitsBegun.load(std::memory_order_relaxed);
}

EnvelopeFit fitEnvelope(const Accelerogram& motion) {
    fitsBegun.fetch_add(1, std::memory_order_relaxed);
    const std::vector<PeakPoint> peaks = halfCyclePeaks(motion);
    if (peaks.size() < 3)
        throw std::invalid_argument("the motion has " + std::to_string(peaks.size()) +
                                    " half-cycle peaks: at least 3 are needed to fit an envelope");
    const FitPeaks p = fitPeaks(peaks, motion.dt);
    FitPoint best;
    for (const EnvelopeStart& s : envelopeStarts(p, 3)) {
        const double x = std::clamp(s.x, kMinX, kMaxX);
        const FitPoint r = refine(p, evaluateFit(p, x, std::clamp(s.z, kMinZ, maxZ(x))));
        if (r.sse < best.sse) best = r;
    }
    const double alpha = std::exp(best.x);
    return {alpha, alpha + alpha * ratioOf(best.z), best.scale,
            std::sqrt(std::max(0.0, best.sse) / static_cast<double>(peaks.size())), peaks.size()};
}

} // namespace kinstab
