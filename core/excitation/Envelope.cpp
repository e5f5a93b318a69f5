// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/excitation/Envelope.h"

#include "core/base/NameTable.h"

#include "core/base/TextInput.h"

#include "core/numerics/RootFinding.h"

#include <cmath>
#include <limits>
#include <sstream>

namespace kinstab {

Envelope Envelope::fromPreset(EnvelopePreset p) {
    // alpha, beta fitted to Table 4's tau_rise and tau_dur (docs/theory.md §3): round values that
    // reproduce the table to 3 digits, surely the originals.
    switch (p) {
    case EnvelopePreset::Fast:
        return {0.01, 2.0, p};
    case EnvelopePreset::Moderate:
        return {0.15, 0.40, p};
    case EnvelopePreset::Slow:
        return {0.04, 0.40, p};
    }
    return {};
}

CharacteristicTimes table4Times(EnvelopePreset p) {
    switch (p) {
    case EnvelopePreset::Fast:
        return {3.38, 27.78, 732.11};
    case EnvelopePreset::Moderate:
        return {8.92, 37.89, 113.80};
    case EnvelopePreset::Slow:
        return {12.81, 63.13, 266.23};
    }
    return {};
}

namespace {
// e(t) written as exp(-alpha t) * (-expm1(-(beta - alpha) t)): no cancellation when alpha ~ beta.
double envelopeValue(double alpha, double beta, double t) {
    return std::exp(-alpha * t) * -std::expm1(-(beta - alpha) * t);
}
double envelopeSlope(double alpha, double beta, double t) {
    return -alpha * std::exp(-alpha * t) + beta * std::exp(-beta * t);
}
double envelopePeakTime(double alpha, double beta) {
    if (alpha <= 0.0) return std::numeric_limits<double>::infinity();
    const double d = beta - alpha;
    // ln(beta/alpha)/(beta-alpha), with log1p for alpha ~ beta.
    return std::log1p(d / alpha) / d;
}
} // namespace

CharacteristicTimes Envelope::computedTimes(double tstar) const {
    CharacteristicTimes c;
    const double tPeak = envelopePeakTime(alpha, beta);
    const double eMax = std::isfinite(tPeak) ? envelopeValue(alpha, beta, tPeak) : 1.0;
    const double half = 0.5 * eMax;
    auto fdf = [&](double t, double& f, double& df) {
        f = envelopeValue(alpha, beta, t) - half;
        df = envelopeSlope(alpha, beta, t);
    };
    // Rising half-maximum: e is increasing on (0, tPeak).
    double hiRise = std::isfinite(tPeak) ? tPeak : 1.0;
    while (!std::isfinite(tPeak) && envelopeValue(alpha, beta, hiRise) < half)
        hiRise *= 2.0;
    c.tauRise =
        safeguardedNewton(fdf, 0.0, hiRise, -half, envelopeValue(alpha, beta, hiRise) - half).x /
        tstar;
    c.tauMax = tPeak / tstar;
    if (!std::isfinite(tPeak)) {
        c.tauDur = std::numeric_limits<double>::infinity();
        return c;
    }
    double hi = 2.0 * tPeak;
    while (envelopeValue(alpha, beta, hi) > half)
        hi *= 2.0;
    c.tauDur =
        safeguardedNewton(fdf, tPeak, hi, eMax - half, envelopeValue(alpha, beta, hi) - half).x /
        tstar;
    return c;
}

CharacteristicTimes Envelope::scalingTimes(double tstar) const {
    return preset ? table4Times(*preset) : computedTimes(tstar);
}

double Envelope::tauRef(TauScale scale, double tstar) const {
    const CharacteristicTimes c = scalingTimes(tstar);
    switch (scale) {
    case TauScale::TauRise:
        return c.tauRise;
    case TauScale::TauMax:
        return c.tauMax;
    case TauScale::TauDur:
        return c.tauDur;
    case TauScale::One:
        return 1.0;
    }
    return 1.0;
}

std::string Envelope::name() const {
    if (preset) return presetName(*preset);
    std::ostringstream s;
    s << "alpha=" << alpha << "/s, beta=" << beta << "/s";
    return s.str();
}

// EnvelopePreset's names, in its declaration order (Fast, Moderate, Slow).
constexpr std::array<const char*, 3> kPresetNames = {"fast", "moderate", "slow"};
static_assert(kPresetNames.size() == static_cast<std::size_t>(EnvelopePreset::Slow) + 1);

std::optional<EnvelopePreset> presetFromName(const std::string& name) {
    return enumFromName<EnvelopePreset>(kPresetNames, name);
}

std::string presetName(EnvelopePreset p) {
    return enumName(kPresetNames, p);
}

// TauScale's names, in its declaration order (TauRise, TauMax, TauDur, One).
constexpr std::array<const char*, 4> kTauScaleNames = {"tau_rise", "tau_max", "tau_dur", "one"};
static_assert(kTauScaleNames.size() == static_cast<std::size_t>(TauScale::One) + 1);

std::optional<TauScale> tauScaleFromName(const std::string& name) {
    return enumFromName<TauScale>(kTauScaleNames, name);
}

std::string tauScaleName(TauScale s) {
    return enumName(kTauScaleNames, s);
}

constexpr std::array<const char*, 4> kGammaScaleLabels = {"γc = τrise/τc", "γc = τmax/τc",
                                                          "γc = τdur/τc", "γc = 1/τc"};
static_assert(kGammaScaleLabels.size() == kTauScaleNames.size());

std::string gammaScaleLabel(TauScale s) {
    return enumName(kGammaScaleLabels, s);
}

InputProblem checkEnvelope(double alpha, double beta) {
    if (InputProblem p = checkInput(kAlphaInput, alpha); !p.empty()) return p;
    if (InputProblem p = checkInput(kBetaInput, beta); !p.empty()) return p;
    if (!(beta > alpha))
        return {"beta", beta, "1/s",
                "envelope rise rate must exceed alpha = " + formatDouble(alpha)};
    return {};
}

std::string validateEnvelope(double alpha, double beta) {
    return describe(checkEnvelope(alpha, beta));
}

} // namespace kinstab
