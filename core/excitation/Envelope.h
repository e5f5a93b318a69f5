// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The envelope e(t) = exp(-alpha t) - exp(-beta t) of the paper's floor acceleration
// (Furgerson 1980, ch. IV) and its three presets.

#include "core/base/NumberInput.h"

#include <optional>
#include <string>

namespace kinstab {

enum class EnvelopePreset { Fast, Moderate, Slow };

// Characteristic times of an envelope, in dimensionless time tau = t / t*.
struct CharacteristicTimes {
    double tauRise = 0; // first half-maximum point of e
    double tauMax = 0;  // maximum of e
    double tauDur = 0;  // second half-maximum point of e (inf when e never falls to half)
};

enum class TauScale { TauRise, TauMax, TauDur, One };

struct Envelope {
    double alpha = 0.15; // 1/s
    double beta = 0.40;  // 1/s
    std::optional<EnvelopePreset> preset;

    static Envelope fromPreset(EnvelopePreset p);
    // Times computed from alpha, beta and t*.
    CharacteristicTimes computedTimes(double tstar) const;
    // The times the gamma_c scaling uses: Table 4's printed values for a preset (that is what
    // the paper's figures use), the computed ones otherwise.
    CharacteristicTimes scalingTimes(double tstar) const;
    double tauRef(TauScale scale, double tstar) const;
    std::string name() const;
};

// Table 4 of the paper (t* = 0.099 s).
CharacteristicTimes table4Times(EnvelopePreset p);
std::optional<EnvelopePreset> presetFromName(const std::string& name);
std::string presetName(EnvelopePreset p);
std::optional<TauScale> tauScaleFromName(const std::string& name);
std::string tauScaleName(TauScale s);
// The γc scale as a figure's axis and the report's symbol table write it: "γc = τmax/τc"
// (UTF-8). One spelling for the GUI's surface and slice and the report's figures.
std::string gammaScaleLabel(TauScale s);

// Largest β (and so α < β) of an envelope, 1/s: a rise time of 0.1 ms is no earthquake's.
inline constexpr double kMaxEnvelopeRate = 1e4;
// α, the decay of the envelope, 1/s: 1e-3 is an e-folding time of 17 minutes, longer than any
// earthquake's strong motion (the fast preset's 0.01 is 100 s); a slower decay only lengthens
// every run (α = 1e-9 runs for hours) without changing what a building feels.
inline constexpr NumberInput kAlphaInput{
    "alpha", "1/s", {1e-3, kMaxEnvelopeRate}, 0.15, "envelope decay rate"};
// β, the rise of the envelope, 1/s; it must also exceed α (validateEnvelope).
inline constexpr NumberInput kBetaInput{
    "beta", "1/s", {1e-3, kMaxEnvelopeRate, true}, 0.40, "envelope rise rate"};

// Validates alpha/beta (each in its range, β > α): the problem names "alpha" or "beta".
InputProblem checkEnvelope(double alpha, double beta);
// The same as a message ("alpha = ... 1/s: ..."), or empty.
std::string validateEnvelope(double alpha, double beta);

} // namespace kinstab
