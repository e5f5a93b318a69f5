// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/excitation/EnvelopeFit.h"

#include "core/excitation/EnvelopeFitStart.h"

#include <algorithm>
#include <array>
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

// The second coordinate z: r = beta / alpha - 1 = 1 + z below r = 1, exp(z) above (z = ln r).
// Toward beta -> alpha f is a polynomial in r, so Newton reaches the valley's end in a few steps
// where in ln r it would creep by about one unit a step.
double ratioOf(double z) {
    return z < 0.0 ? 1.0 + z : std::exp(z);
}
double zOfY(double y) {
    return y < 0.0 ? std::exp(y) - 1.0 : y;
}
constexpr double kMinZ = kMinRatio - 1.0;
double maxZ(double x) {
    return std::log(kMaxBeta / std::exp(x) - 1.0); // > 0: alpha <= 1e3
}

// exp(-690) = 2.2e-300: past it a peak's terms (e, its derivatives, their products) are at most
// subnormal, which adds nothing to the sums and costs the CPU ~100 cycles each.
constexpr double kNegligibleDecay = 690.0;

// The reduced objective f(x, z) = min_c sum (p - c e)^2 (variable projection: c = <e,p>/<e,e>)
// at x = ln alpha and z, with its gradient and Hessian in (x, z).
struct Point {
    double x = 0, y = 0, // y: z
        sse = std::numeric_limits<double>::infinity(), scale = 0;
    std::array<double, 2> g{};
    std::array<double, 3> h{}; // xx, xy, yy
};

// e = exp(-alpha t) - exp(-beta t) = -A expm1(-w t) with w = beta - alpha (no cancellation as beta
// nears alpha, the valley of the Fig. 27 fits); d = de/dx, de/dy; dd = the second derivatives.
Point evaluate(const std::vector<PeakPoint>& p, double pp, double x, double z) {
    const double alpha = std::exp(x), w = alpha * ratioOf(z), beta = alpha + w;
    // ee, ep, <e,dx>, <e,dy>, <p,dx>, <p,dy>, <dx,dx>, <dx,dy>, <dy,dy>, <p,dd..>, <e,dd..>
    double s[15] = {};
    for (const PeakPoint& q : p) {
        const double t = q.time, v = q.value;
        if (alpha * t > kNegligibleDecay) continue; // e and its derivatives below 1e-300
        const double a = std::exp(-alpha * t), m = std::expm1(-w * t);
        const double e = -a * m, b = a + a * m;
        const double dx = t * (w * b - alpha * e), dy = t * w * b;
        const double dxx = dx + t * t * (alpha * alpha * e - w * (alpha + beta) * b);
        const double dxy = dy * (1.0 - t * beta), dyy = dy * (1.0 - t * w);
        const double terms[15] = {e * e,   e * v,   e * dx,  e * dy,  v * dx,
                                  v * dy,  dx * dx, dx * dy, dy * dy, v * dxx,
                                  v * dxy, v * dyy, e * dxx, e * dxy, e * dyy};
        for (int k = 0; k < 15; ++k)
            s[k] += terms[k];
    }
    Point r{x, z};
    const double D = s[0], N = s[1];
    if (!(D > 0.0) || !(N > 0.0)) { // no positive envelope fits: f = pp, flat
        r.sse = pp;
        return r;
    }
    const double c = N / D;
    r.scale = c;
    r.sse = pp - c * N;
    // f_i = -2 c N_i + c^2 D_i with N_i = <p,d_i>, D_i = 2 <e,d_i>; f_ij = -2 (N_i - c D_i)
    // (N_j - c D_j) / D + c (c D_ij - 2 N_ij) with D_ij = 2 (<d_i,d_j> + <e,d_ij>).
    const double u[2] = {s[4] - 2.0 * c * s[2], s[5] - 2.0 * c * s[3]};
    r.g = {-2.0 * c * s[4] + 2.0 * c * c * s[2], -2.0 * c * s[5] + 2.0 * c * c * s[3]};
    for (int k = 0; k < 3; ++k) {
        const int i = k == 2 ? 1 : 0, j = k == 0 ? 0 : 1;
        const double dij = 2.0 * (s[6 + k] + s[12 + k]);
        r.h[static_cast<std::size_t>(k)] = -2.0 * u[i] * u[j] / D + c * (c * dij - 2.0 * s[9 + k]);
    }
    if (z < 0.0) { // from y = ln(1 + z): dy/dz = 1 / r, d2y/dz2 = -1 / r^2
        const double inv = 1.0 / ratioOf(z);
        r.h[2] = r.h[2] * inv * inv - r.g[1] * inv * inv;
        r.h[1] *= inv;
        r.g[1] *= inv;
    }
    return r;
}

struct Box {
    double lo[2], hi[2];
};

Box boxAt(double x) {
    return {{kMinX, kMinZ}, {kMaxX, maxZ(x)}};
}

bool atBound(const Point& p, int i, double direction) {
    const Box b = boxAt(p.x);
    const double at = i == 0 ? p.x : p.y;
    return (at <= b.lo[i] && direction < 0.0) || (at >= b.hi[i] && direction > 0.0);
}

// The damped Newton step (H + lambda diag H) d = -g on the free coordinates (Marquardt's
// scaling: z's curvature is orders below x's along the valley); lambda grows until the matrix
// is positive definite, so that d descends.
std::array<double, 2> dampedStep(const Point& p, double& lambda, std::array<bool, 2> free) {
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
std::array<double, 2> newtonStep(const Point& p, double& lambda) {
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
std::array<double, 2> stepInBox(const Point& cur, std::array<double, 2> d) {
    const double big = std::max(std::abs(d[0]), std::abs(d[1]));
    if (big > 1.5) d = {d[0] * 1.5 / big, d[1] * 1.5 / big};
    const Box box = boxAt(cur.x);
    const double at[2] = {cur.x, cur.y};
    double length = 1.0;
    int edge = -1;
    double edgeValue = 0.0;
    for (int i = 0; i < 2; ++i) {
        const double di = d[static_cast<std::size_t>(i)];
        const double bound = at[i] + di < box.lo[i] ? box.lo[i] : box.hi[i];
        if ((at[i] + di < box.lo[i] || at[i] + di > box.hi[i]) && (bound - at[i]) / di < length)
            length = (bound - at[i]) / di, edge = i, edgeValue = bound;
    }
    std::array<double, 2> to = {cur.x + length * d[0], cur.y + length * d[1]};
    if (edge >= 0) to[static_cast<std::size_t>(edge)] = edgeValue;
    to[0] = std::clamp(to[0], kMinX, kMaxX);
    to[1] = std::clamp(to[1], kMinZ, maxZ(to[0]));
    return to;
}

// Levenberg-Marquardt-damped Newton from the start, kept in the box; a step is taken only when
// it lowers f, so the result is never worse than the start. Ends when an undamped Newton step is
// below 1e-5 (quadratic convergence leaves ~1e-10 in x and z, ~1e-20 of f after it), or when no
// step longer than 1e-10 descends.
Point refine(const std::vector<PeakPoint>& p, double pp, Point cur) {
    double trust = 0.0; // damping after rejected steps
    for (int it = 0; it < 60; ++it) {
        double lambda = trust; // raised further where H is not positive definite
        const std::array<double, 2> to = stepInBox(cur, newtonStep(cur, lambda));
        const double moved = std::max(std::abs(to[0] - cur.x), std::abs(to[1] - cur.y));
        if (!(moved > 1e-10)) break; // nothing left to gain at double precision
        const bool undamped = lambda < 1e-6;
        const Point next = evaluate(p, pp, to[0], to[1]);
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

EnvelopeFit fitEnvelope(const Accelerogram& motion) {
    const std::vector<PeakPoint> p = halfCyclePeaks(motion);
    if (p.size() < 3)
        throw std::invalid_argument("the motion has " + std::to_string(p.size()) +
                                    " half-cycle peaks: at least 3 are needed to fit an envelope");
    double pp = 0.0;
    for (const PeakPoint& q : p)
        pp += q.value * q.value;
    Point best;
    for (const EnvelopeStart& s : envelopeStarts(p, pp, 3)) {
        const double x = std::clamp(s.x, kMinX, kMaxX);
        const Point r = refine(p, pp, evaluate(p, pp, x, std::clamp(zOfY(s.y), kMinZ, maxZ(x))));
        if (r.sse < best.sse) best = r;
    }
    const double alpha = std::exp(best.x);
    return {alpha, alpha + alpha * ratioOf(best.y), best.scale,
            std::sqrt(std::max(0.0, best.sse) / static_cast<double>(p.size())), p.size()};
}

} // namespace kinstab
