#include "core/excitation/EnvelopedSine.h"

#include "core/numerics/RootFinding.h"

#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

namespace kinstab {

namespace {
// 10-point Gauss-Legendre on [-1, 1]. Used for the integrals over short intervals, where the
// closed forms lose digits to cancellation (grazing slips last microseconds).
constexpr std::array<double, 5> kGlX = {0.1488743389816312, 0.4333953941292472, 0.6794095682990244,
                                        0.8650633666889845, 0.9739065285171717};
constexpr std::array<double, 5> kGlW = {0.2955242247147529, 0.2692667193099963, 0.2190863625159820,
                                        0.1494513491505806, 0.0666713443086881};
} // namespace

EnvelopedSine::EnvelopedSine(const Envelope& env, double amplitude, double frequencyHz,
                             double tstar)
    : amplitude_(amplitude), p_(env.alpha * tstar), q_(env.beta * tstar),
      omega_(2.0 * std::numbers::pi * frequencyHz * tstar), halfPeriod_(std::numbers::pi / omega_),
      tauEnvelopePeak_(p_ > 0.0 ? std::log1p((q_ - p_) / p_) / (q_ - p_)
                                : std::numeric_limits<double>::infinity()) {
    sMax_ = computeSMax();
    scale_ = amplitude_ / sMax_;
}

double EnvelopedSine::envelopeAt(double tau) const {
    return std::exp(-p_ * tau) * -std::expm1(-(q_ - p_) * tau);
}
double EnvelopedSine::envelopeSlope(double tau) const {
    return -p_ * std::exp(-p_ * tau) + q_ * std::exp(-q_ * tau);
}
double EnvelopedSine::envelopeCurvature(double tau) const {
    return p_ * p_ * std::exp(-p_ * tau) - q_ * q_ * std::exp(-q_ * tau);
}

double EnvelopedSine::accel(double tau) const {
    return scale_ * envelopeAt(tau) * std::sin(omega_ * tau);
}

double EnvelopedSine::accelSlope(double tau) const {
    const double s = std::sin(omega_ * tau), c = std::cos(omega_ * tau);
    return scale_ * (envelopeSlope(tau) * s + omega_ * envelopeAt(tau) * c);
}

double EnvelopedSine::primitive1(double l, double tau) const {
    const double d = l * l + omega_ * omega_;
    return -std::exp(-l * tau) * (l * std::sin(omega_ * tau) + omega_ * std::cos(omega_ * tau)) / d;
}

double EnvelopedSine::primitive2(double l, double tau) const {
    const double d = l * l + omega_ * omega_;
    const double w = omega_;
    return std::exp(-l * tau) *
           ((l * l - w * w) * std::sin(w * tau) + 2.0 * l * w * std::cos(w * tau)) / (d * d);
}

double EnvelopedSine::velocityChange(double t0, double t1) const {
    const double h = t1 - t0;
    if (std::abs(omega_ * h) < 0.5) {
        const double m = 0.5 * (t0 + t1), r = 0.5 * h;
        double sum = 0.0;
        for (std::size_t i = 0; i < kGlX.size(); ++i)
            sum += kGlW[i] * (accel(m - r * kGlX[i]) + accel(m + r * kGlX[i]));
        return r * sum;
    }
    return scale_ *
           ((primitive1(p_, t1) - primitive1(p_, t0)) - (primitive1(q_, t1) - primitive1(q_, t0)));
}

double EnvelopedSine::displacementChange(double t0, double t1) const {
    const double h = t1 - t0;
    if (std::abs(omega_ * h) < 0.5) {
        // int_{t0}^{t1} (t1 - s) a(s) ds
        const double m = 0.5 * (t0 + t1), r = 0.5 * h;
        double sum = 0.0;
        // t1 - s written as r (1 +- x_i): t1 - s itself would cancel when t >> h.
        for (std::size_t i = 0; i < kGlX.size(); ++i) {
            const double sl = m - r * kGlX[i], sr = m + r * kGlX[i];
            sum += kGlW[i] * (r * (1.0 + kGlX[i]) * accel(sl) + r * (1.0 - kGlX[i]) * accel(sr));
        }
        return r * sum;
    }
    auto part = [&](double l) {
        return primitive2(l, t1) - primitive2(l, t0) - primitive1(l, t0) * h;
    };
    return scale_ * (part(p_) - part(q_));
}

double EnvelopedSine::segmentEnd(double segmentStart) const {
    // Half-periods of the sine: on each, |sin| and the envelope are log-concave, so |a| is
    // unimodal and crosses a level at most twice (NUMERICS.md §5.2).
    const double k = std::floor(segmentStart / halfPeriod_ + 1e-9);
    double end = (k + 1.0) * halfPeriod_;
    if (end <= segmentStart) end = (k + 2.0) * halfPeriod_;
    return end;
}

double EnvelopedSine::halfPeriodPeak(long k) const {
    const double lo = static_cast<double>(k) * halfPeriod_;
    const double hi = lo + halfPeriod_;
    // d/dtau log|e sin| = e'/e + omega cot(omega tau): strictly decreasing from +inf to -inf.
    auto fdf = [&](double t, double& f, double& df) {
        const double e = envelopeAt(t), e1 = envelopeSlope(t), e2 = envelopeCurvature(t);
        const double s = std::sin(omega_ * t), c = std::cos(omega_ * t);
        f = e1 / e + omega_ * c / s;
        df = (e2 * e - e1 * e1) / (e * e) - omega_ * omega_ / (s * s);
    };
    const double eps = 1e-12 * halfPeriod_;
    return safeguardedNewton(fdf, lo + eps, hi - eps, 1.0, -1.0).x;
}

Crossings EnvelopedSine::crossings(double level, double segmentStart, double segmentEnd) const {
    Crossings out;
    if (level == 0.0) return out;
    const long k = std::lround(segmentStart / halfPeriod_);
    const double sign = (k % 2 == 0) ? 1.0 : -1.0;
    if ((level > 0.0) != (sign > 0.0)) return out;
    const double target = std::abs(level);
    if (boundOn(segmentStart, segmentEnd) <= target) return out;
    const double m = halfPeriodPeak(k);
    const double peakValue = sign * accel(m);
    if (!(peakValue > target)) return out; // touching is not crossing
    auto fdf = [&](double t, double& f, double& df) {
        f = sign * accel(t) - target;
        df = sign * accelSlope(t);
    };
    const double lo = static_cast<double>(k) * halfPeriod_, hi = lo + halfPeriod_;
    out.add(safeguardedNewton(fdf, lo, m, -target, peakValue - target).x);
    out.add(safeguardedNewton(fdf, m, hi, peakValue - target, -target).x);
    return out;
}

double EnvelopedSine::boundAfter(double tau) const {
    if (!std::isfinite(tauEnvelopePeak_)) return scale_; // e rises to 1 and stays
    return scale_ * envelopeAt(std::max(tau, tauEnvelopePeak_));
}

double EnvelopedSine::boundOn(double lo, double hi) const {
    if (hi < tauEnvelopePeak_) return scale_ * envelopeAt(hi);
    if (lo > tauEnvelopePeak_) return scale_ * envelopeAt(lo);
    return scale_ * envelopeAt(tauEnvelopePeak_);
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
    const long k0 = static_cast<long>(std::floor(tauEnvelopePeak_ / halfPeriod_));
    double best = peakOf(k0);
    for (long k = k0 + 1;; ++k) {
        const double v = peakOf(k);
        if (v <= best) break;
        best = v;
    }
    for (long k = k0 - 1; k >= 0; --k) {
        const double v = peakOf(k);
        if (v <= best) break;
        best = v;
    }
    return best;
}

std::string validateEnvelopedSine(double amplitude, double frequencyHz, double tstar) {
    std::ostringstream s;
    if (!std::isfinite(amplitude) || amplitude < 0.0 || amplitude > 1000.0)
        s << "amplitude = " << amplitude << " g: must be between 0 and 1000";
    else if (!std::isfinite(frequencyHz) || frequencyHz <= 0.0 || frequencyHz > 1000.0)
        s << "frequency = " << frequencyHz << " Hz: must be > 0 and at most 1000";
    else if (!std::isfinite(tstar) || tstar <= 0.0 || tstar > 100.0)
        s << "tstar = " << tstar << " s: must be > 0 and at most 100";
    return s.str();
}

} // namespace kinstab
