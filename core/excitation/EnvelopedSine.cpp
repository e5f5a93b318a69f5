// SPDX-License-Identifier: GPL-3.0-or-later
// Over 400 lines with its header for a reason: one excitation's closed forms (value, slopes,
// integrals, bounds, the hump search) share one memo of exponentials, and the header states each
// formula.
#include "core/excitation/EnvelopedSine.h"

#include "core/base/InputLimits.h"
#include "core/base/InternalError.h"
#include "core/base/TextInput.h"
#include "core/excitation/FrequencyRange.h"
#include "core/numerics/HalleyRoot.h"
#include "core/numerics/RootFinding.h"

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

namespace kinstab {

EnvelopedSine::EnvelopedSine(const Envelope& env, double amplitude, double frequencyHz,
                             double tstar)
    : amplitude_(amplitude), p_(env.alpha * tstar), q_(env.beta * tstar),
      omega_(2.0 * std::numbers::pi * frequencyHz * tstar), halfPeriod_(std::numbers::pi / omega_),
      tauEnvelopePeak_(p_ > 0.0 ? std::log1p((q_ - p_) / p_) / (q_ - p_)
                                : std::numeric_limits<double>::infinity()),
      integrals_(p_, q_, omega_) {
    sMax_ = computeSMax();
    scale_ = amplitude_ / sMax_;
}

long& EnvelopedSine::evaluationCount() {
    thread_local long count = 0;
    return count;
}

double EnvelopedSine::envelopeAt(double tau) const {
    return std::exp(-p_ * tau) * -std::expm1(-(q_ - p_) * tau);
}

// e, e' and e'' from two exponentials: e^{-q tau} = e^{-p tau} (1 + m), m = expm1(-(q - p) tau),
// and e = -e^{-p tau} m keeps its digits when q ~ p (docs/theory.md §6.6 case 12).
void EnvelopedSine::envelopeAndSlope(double tau, double& e, double& de) const {
    const double ep = std::exp(-p_ * tau);
    const double m = std::expm1(-(q_ - p_) * tau);
    // e' = -p e^{-p tau} + q e^{-q tau} = e^{-p tau} (d + q m) and
    // e'' = e^{-p tau} (-d (p + q) - q^2 m), d = q - p: the two terms of the textbook forms
    // are nearly equal when q ~ p (at beta = alpha (1 + 1e-15) e' kept one digit).
    const double d = q_ - p_;
    e = -ep * m;
    de = ep * (d + q_ * m);
}

// e'/e and e''/e from m = expm1(-(q - p) tau) alone (the forms above divided by e = -e^{-p tau} m):
// the factor e^{-p tau} cancels before it is formed, so the ratios stay finite where e^{-p tau}
// underflows (long times, low frequencies), where e'/e computed as a quotient is 0/0.
void EnvelopedSine::logSlopes(double tau, double& r1, double& r2) const {
    const double m = std::expm1(-(q_ - p_) * tau);
    const double d = q_ - p_;
    r1 = -(d + q_ * m) / m;
    r2 = (d * (p_ + q_) + q_ * q_ * m) / m;
}

double EnvelopedSine::accel(double tau) const {
    return scale_ * envelopeAt(tau) * std::sin(omega_ * tau);
}

double EnvelopedSine::accelSlope(double tau) const {
    double a = 0.0, da = 0.0;
    accelAndSlope(tau, a, da);
    return da;
}

void EnvelopedSine::accelAndSlope(double tau, double& a, double& da) const {
    double e = 0.0, de = 0.0;
    envelopeAndSlope(tau, e, de);
    const double s = std::sin(omega_ * tau), c = std::cos(omega_ * tau);
    a = scale_ * e * s;
    da = scale_ * (de * s + omega_ * e * c);
}

// With e^(k) = e^{-p tau} E_k (E_0 = -m, E_1 = d + q m, E_2 = -d (p + q) - q^2 m,
// E_3 = d (p^2 + p q + q^2) + q^3 m; m = expm1(-(q - p) tau), as envelopeAndSlope) and Leibniz's
// rule on e sin(omega tau). a and a' are accelAndSlope's, bit for bit.
void EnvelopedSine::accelDerivatives(double tau, double out[4]) const {
    const double ep = std::exp(-p_ * tau);
    const double m = std::expm1(-(q_ - p_) * tau);
    const double d = q_ - p_;
    const double e = -ep * m, de = ep * (d + q_ * m);
    const double d2e = ep * (-d * (p_ + q_) - q_ * q_ * m);
    const double d3e = ep * (d * (p_ * p_ + p_ * q_ + q_ * q_) + q_ * q_ * q_ * m);
    const double s = std::sin(omega_ * tau), c = std::cos(omega_ * tau), w = omega_;
    out[0] = scale_ * e * s;
    out[1] = scale_ * (de * s + w * e * c);
    out[2] = scale_ * ((d2e - w * w * e) * s + 2.0 * w * de * c);
    out[3] = scale_ * ((d3e - 3.0 * w * w * de) * s + w * (3.0 * d2e - w * w * e) * c);
}

double EnvelopedSine::velocityChange(double t0, double t1) const {
    return scale_ * integrals_.first(t0, t1 - t0);
}

double EnvelopedSine::velocityChangeAndAccel(double t0, double t1, double& accelAtT1) const {
    double shape = 0.0;
    const double dv = scale_ * integrals_.first(t0, t1 - t0, &shape);
    accelAtT1 = scale_ * shape;
    return dv;
}

double EnvelopedSine::velocityChangeAndSlopes(double t0, double t1, AccelAt& at) const {
    ShapeAt g;
    const double dv = scale_ * integrals_.firstWithShape(t0, t1 - t0, g);
    at = {scale_ * g.g, scale_ * g.dg, scale_ * g.d2g};
    return dv;
}

double EnvelopedSine::displacementChange(double t0, double t1) const {
    return scale_ * integrals_.second(t0, t1 - t0);
}

double EnvelopedSine::velocityAndDisplacementChange(double t0, double t1, double& dx) const {
    double second = 0.0;
    const double dv = scale_ * integrals_.both(t0, t1 - t0, second);
    dx = scale_ * second;
    return dv;
}

double EnvelopedSine::changesAndAccel(double t0, double t1, double& dx, double& accelAtT1) const {
    double second = 0.0, shape = 0.0;
    const double dv = scale_ * integrals_.both(t0, t1 - t0, second, &shape);
    dx = scale_ * second;
    accelAtT1 = scale_ * shape;
    return dv;
}

long EnvelopedSine::halfPeriodIndex(double segmentStart) const {
    return static_cast<long>(std::floor(segmentStart / halfPeriod_ + 1e-9));
}

double EnvelopedSine::segmentEnd(double segmentStart) const {
    // Half-periods of the sine: on each, |sin| and the envelope are log-concave, so |a| is
    // unimodal and crosses a level at most twice (docs/theory.md §6.3).
    const double k = static_cast<double>(halfPeriodIndex(segmentStart));
    double end = (k + 1.0) * halfPeriod_;
    if (end <= segmentStart) end = (k + 2.0) * halfPeriod_;
    return end;
}

// Each half-period is one hump (see segmentEnd()), with the sine's sign.
int EnvelopedSine::humpSign(double lo, double /*hi*/) const {
    return halfPeriodIndex(lo) % 2 == 0 ? 1 : -1;
}

double EnvelopedSine::halfPeriodPeak(long k) const {
    const double lo = static_cast<double>(k) * halfPeriod_;
    const double hi = lo + halfPeriod_;
    // d/dtau log|e sin| = e'/e + omega cot(omega tau): strictly decreasing from +inf to -inf.
    auto fdf = [&](double t, double& f, double& df) {
        ++evaluationCount();
        double r1 = 0.0, r2 = 0.0;
        logSlopes(t, r1, r2);
        const double s = std::sin(omega_ * t), c = std::cos(omega_ * t);
        f = r1 + omega_ * c / s;
        df = r2 - r1 * r1 - omega_ * omega_ / (s * s);
    };
    const double eps = 1e-12 * halfPeriod_;
    return safeguardedNewton(fdf, lo + eps, hi - eps, 1.0, -1.0, 200, peakGuess(k)).x;
}

// With e'/e frozen at its midpoint value lambda, the peak is where
// cot(omega (tau - lo)) = -lambda/omega: within ~1e-3 of the true one.
double EnvelopedSine::peakGuess(long k, double* logSlope) const {
    const double lo = static_cast<double>(k) * halfPeriod_;
    ++evaluationCount();
    double lambda = 0.0, r2 = 0.0;
    logSlopes(lo + 0.5 * halfPeriod_, lambda, r2);
    if (logSlope) *logSlope = lambda;
    return lo + (0.5 * std::numbers::pi + std::atan(lambda / omega_)) / omega_;
}

// A solver asks for a hump's rising and then its falling crossing, and a slab that sticks and
// slides again on the same hump asks for one of them twice: remember the last hump per thread,
// with its crossings once solved. The key holds every input, so objects can never see each
// other's values.
struct EnvelopedSine::HumpMemo {
    std::array<double, 5> key{};
    long k = -1;
    std::optional<Hump> hump;
    std::array<double, 2> root{}; // falling, rising; NaN until solved
};

EnvelopedSine::HumpMemo& EnvelopedSine::humpMemo(long k, double target) const {
    thread_local HumpMemo memo;
    const std::array<double, 5> key{p_, q_, omega_, scale_, target};
    if (memo.k != k || memo.key != key) {
        memo.hump = findHumpAbove(k, target);
        memo.k = k;
        memo.key = key;
        memo.root.fill(std::numeric_limits<double>::quiet_NaN());
    }
    return memo;
}

double EnvelopedSine::humpRootOnce(HumpMemo& memo, double target, bool rising) const {
    double& root = memo.root[rising ? 1 : 0];
    if (std::isnan(root)) root = humpRoot(*memo.hump, target, rising);
    return root;
}

std::optional<EnvelopedSine::Hump> EnvelopedSine::findHumpAbove(long k, double target) const {
    const double lo = static_cast<double>(k) * halfPeriod_;
    if (boundOn(lo, lo + halfPeriod_) <= target) return std::nullopt;
    // |a| is unimodal on the half-period, so any point above the level splits its two
    // crossings: the peak guess usually is one; only near grazing is the true peak needed.
    Hump h{k, k % 2 == 0 ? 1.0 : -1.0, 0.0, 0.0, 0.0, 0.0};
    h.m = peakGuess(k, &h.logSlope);
    for (int attempt = 0; attempt < 2; ++attempt) {
        if (attempt == 1) h.m = halfPeriodPeak(k);
        ++evaluationCount();
        h.envelope = envelopeAt(h.m);
        h.peakValue = scale_ * h.envelope * std::abs(std::sin(omega_ * h.m));
        if (h.peakValue > target) return h;
    }
    return std::nullopt;
}

double EnvelopedSine::humpRoot(const Hump& h, double target, bool rising) const {
    auto fdf = [&](double t, Derivatives& d) {
        ++evaluationCount();
        double a[4];
        accelDerivatives(t, a);
        d = {h.sign * a[0] - target, h.sign * a[1], h.sign * a[2], h.sign * a[3]};
    };
    const double lo = static_cast<double>(h.k) * halfPeriod_, hi = lo + halfPeriod_;
    // First guess: the envelope frozen at its value at m, |a| = level where
    // |sin(omega (tau - lo))| = level / (scale e(m)); then twice the same step with the envelope
    // at the last guess from a second-order model of log e (no closed-form evaluation). The start
    // is then close enough that one Halley step, whose error a''' tells, usually ends the solve
    // (docs/theory.md §6.3).
    const auto offsetAt = [&](double e) {
        return std::asin(std::min(1.0, target / (scale_ * e))) / omega_;
    };
    // log e about the half-period's middle c to second order: lambda = e'/e there, and
    // rho = (log e)'' = e''/e - lambda^2 from the same m = expm1(-(q - p) c) = -d / (lambda + q).
    const double c = lo + 0.5 * halfPeriod_, d = q_ - p_, m = -d / (h.logSlope + q_);
    const double rho = (d * (p_ + q_) + q_ * q_ * m) / m - h.logSlope * h.logSlope;
    const auto envelopeNear = [&](double t) {
        const double u = t - c, v = h.m - c;
        return h.envelope * std::exp(h.logSlope * (t - h.m) + 0.5 * rho * (u * u - v * v));
    };
    const double first = offsetAt(h.envelope);
    const double guess = rising ? lo + first : hi - first;
    const double second = offsetAt(envelopeNear(guess));
    const double offset = offsetAt(envelopeNear(rising ? lo + second : hi - second));
    return rising
               ? safeguardedHalley(fdf, lo, h.m, -target, h.peakValue - target, 200, lo + offset).x
               : safeguardedHalley(fdf, h.m, hi, h.peakValue - target, -target, 200, hi - offset).x;
}

Crossings EnvelopedSine::crossings(double level, double segmentStart, double segmentEnd) const {
    Crossings out;
    const long k = halfPeriodIndex(segmentStart);
    if (level == 0.0 || (level > 0.0) != (k % 2 == 0)) return out;
    HumpMemo& memo = humpMemo(k, std::abs(level));
    if (!memo.hump) return out;
    // Only the crossings inside the segment: a segment cut short (a duration cap) must not
    // report the half-period's crossings beyond its end.
    for (const bool rising : {true, false}) {
        const double t = humpRootOnce(memo, std::abs(level), rising);
        if (t > segmentStart && t < segmentEnd) out.add(t);
    }
    return out;
}

// Only the root asked for; the rising one lies before m and the falling one after it, so a
// root on the wrong side of (lo, hi) is not even computed.
double EnvelopedSine::humpCrossing(double level, double lo, double hi, bool rising) const {
    constexpr double none = std::numeric_limits<double>::quiet_NaN();
    HumpMemo& memo = humpMemo(halfPeriodIndex(lo), level);
    const auto& hump = memo.hump;
    if (!hump || (rising && lo >= hump->m) || (!rising && hi <= hump->m)) return none;
    const double t = humpRootOnce(memo, level, rising);
    return t > lo && t < hi ? t : none;
}

// A solver asks boundAfter(t) and boundOn(t, ...) of the same segment start, and the hump search
// asks boundOn of its half-period again: remember the last envelope value per thread. The key
// holds every input, so objects can never see each other's values.
double EnvelopedSine::boundEnvelopeAt(double tau) const {
    struct Memo {
        double p = -1, q = -1, tau = std::numeric_limits<double>::quiet_NaN(), e = 0;
    };
    thread_local Memo memo;
    if (memo.tau != tau || memo.p != p_ || memo.q != q_) memo = {p_, q_, tau, envelopeAt(tau)};
    return memo.e;
}

double EnvelopedSine::boundAfter(double tau) const {
    if (!std::isfinite(tauEnvelopePeak_)) return scale_; // e rises to 1 and stays
    return scale_ * boundEnvelopeAt(std::max(tau, tauEnvelopePeak_));
}

double EnvelopedSine::boundOn(double lo, double hi) const {
    if (hi < tauEnvelopePeak_) return scale_ * boundEnvelopeAt(hi);
    if (lo > tauEnvelopePeak_) return scale_ * boundEnvelopeAt(lo);
    return scale_ * boundEnvelopeAt(tauEnvelopePeak_);
}

double EnvelopedSine::computeSMax() const {
    if (!std::isfinite(tauEnvelopePeak_))
        return 1.0; // sup of (1 - e^{-beta t}) |sin|, not attained
    // The half-period maxima rise and then fall with the envelope (Appendix): walk both ways from
    // the half-period that holds the envelope's peak until they fall.
    auto peakOf = [&](long k) {
        const double m = halfPeriodPeak(k);
        return std::abs(envelopeAt(m) * std::sin(omega_ * m));
    };
    // The largest maximum is within a few half-periods of k0 (the envelope changes little over
    // one where the sine is fast; where it is slow, k0 is 0 or 1): kMaxWalk ends a walk that a
    // non-finite value would otherwise keep going, with an error instead of a wrong S_max.
    constexpr long kMaxWalk = 1000;
    const long k0 = static_cast<long>(std::floor(tauEnvelopePeak_ / halfPeriod_));
    double best = peakOf(k0);
    bool ended = false;
    for (long k = k0 + 1; k <= k0 + kMaxWalk && !ended; ++k) {
        const double v = peakOf(k);
        ended = !(v > best);
        if (!ended) best = v;
    }
    for (long k = k0 - 1; k >= 0 && k >= k0 - kMaxWalk && ended; --k) {
        const double v = peakOf(k);
        if (!(v > best)) break;
        best = v;
    }
    if (!ended || !std::isfinite(best) || best <= 0.0)
        throw InternalError("S_max of the enveloped sine (f t* = " +
                            std::to_string(omega_ / (2.0 * std::numbers::pi)) +
                            ") not found: peak " + std::to_string(best));
    return best;
}

InputProblem checkEnvelopedSine(double amplitude, double frequencyHz, double tstar) {
    if (InputProblem p = checkInput(kAmplitudeInput, amplitude); !p.empty()) return p;
    if (InputProblem p = checkInput(kFrequencyInput, frequencyHz); !p.empty()) return p;
    return checkInput(kTstarInput, tstar);
}

std::string validateEnvelopedSine(double amplitude, double frequencyHz, double tstar) {
    return describe(checkEnvelopedSine(amplitude, frequencyHz, tstar));
}

} // namespace kinstab
