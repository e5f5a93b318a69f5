// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/slab/PlanarCase.h"

#include "core/excitation/EnvelopedSine.h"
#include "core/excitation/FrequencyRange.h"
#include "core/slab/SlabLimits.h"

#include <cmath>
#include <sstream>

namespace kinstab {

std::string normalizationName(PlanarNormalization n) {
    return n == PlanarNormalization::Product ? "product" : "envelope";
}

std::optional<PlanarNormalization> normalizationFromName(const std::string& name) {
    if (name == "product") return PlanarNormalization::Product;
    if (name == "envelope") return PlanarNormalization::Envelope;
    return std::nullopt;
}

std::string validatePlanarCase(const PlanarCase& c) {
    std::string e = validateEnvelope(c.envelope.alpha, c.envelope.beta);
    if (e.empty()) e = validatePlanarParams(c.slab);
    if (!e.empty()) return e;
    std::ostringstream s;
    if (!kTstarRange.contains(c.tstar))
        s << "tstar = " << c.tstar << " s: must be > 0 and at most " << kTstarRange.hi;
    else if (!kAyRatioRange.contains(c.ayRatio))
        s << "ay ratio = " << c.ayRatio << ": A_y / A_x must be between " << kAyRatioRange.lo
          << " and " << kAyRatioRange.hi;
    else if (!std::isfinite(c.fyHz) || c.fyHz <= 0.0 || c.fyHz > kMaxFrequencyHz)
        s << "fy = " << c.fyHz << " Hz: must be > 0 and at most " << kMaxFrequencyHz;
    else if (!(c.solver.relTol >= 1e-14 && c.solver.relTol <= 1e-2))
        s << "relative tolerance = " << c.solver.relTol << ": must be between 1e-14 and 1e-2";
    else if (!(c.solver.absTol > 0.0 && c.solver.absTol <= 1e-2))
        s << "absolute tolerance = " << c.solver.absTol << ": must be > 0 and at most 1e-2";
    return s.str();
}

namespace {
// One horizontal component. For the envelope-only normalization the amplitude handed to the
// enveloped sine (which divides by max(e sin)) is rescaled so that the factor is A / max(e).
std::shared_ptr<const Excitation1D> component(const PlanarCase& c, double amplitude, double f) {
    if (c.normalization == PlanarNormalization::Product)
        return std::make_shared<EnvelopedSine>(c.envelope, amplitude, f, c.tstar);
    const EnvelopedSine unit(c.envelope, 1.0, f, c.tstar);
    const double peak = unit.envelopePeakTau();
    const double envelopeMax = std::isfinite(peak) ? unit.envelopeAt(peak) : 1.0;
    return std::make_shared<EnvelopedSine>(c.envelope, amplitude * unit.sMax() / envelopeMax, f,
                                           c.tstar);
}
} // namespace

SlabModel2D planarModel(const PlanarCase& c, double ax, double fxHz) {
    auto x = component(c, ax, fxHz);
    std::shared_ptr<const Excitation1D> y;
    if (c.ayRatio > 0.0 && ax > 0.0) y = component(c, c.ayRatio * ax, c.fyHz);
    return SlabModel2D(std::move(x), std::move(y), c.vertical, c.slab);
}

PlanarResult runPlanar(const PlanarCase& c, double ax, double fxHz) {
    return solvePlanar(planarModel(c, ax, fxHz), c.solver);
}

PointFunction planarPoint(const PlanarCase& c) {
    return [c](double amplitude, double frequency) {
        const PlanarResult r = runPlanar(c, amplitude, frequency);
        return PointResult{r.slab.outcome, r.slab.tauC, r.exitSide};
    };
}

double planarNoSlipAmplitude(const PlanarCase& c) {
    const double nMin = c.vertical ? 1.0 - c.vertical->peak() : 1.0;
    return std::max(0.0, c.slab.mu * nMin / std::hypot(1.0, c.ayRatio));
}

PlanarCase planarCaseSharing(const Slab1DCase& common) {
    PlanarCase c;
    c.envelope = common.envelope;
    c.tstar = common.tstar;
    c.scale = common.scale;
    static_cast<SlabParams&>(c.slab) = common.slab;
    return c;
}

} // namespace kinstab
