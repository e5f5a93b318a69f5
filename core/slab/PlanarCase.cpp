// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/slab/PlanarCase.h"

#include "core/excitation/EnvelopedSine.h"
#include "core/excitation/FrequencyRange.h"
#include "core/slab/SlabInputs.h"

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

InputProblem checkPlanarCase(const PlanarCase& c) {
    const Slab1DCase& k = c.common;
    if (InputProblem e = checkEnvelope(k.envelope.alpha, k.envelope.beta); !e.empty()) return e;
    if (InputProblem e = checkPlanarParams(c.params()); !e.empty()) return e;
    if (InputProblem e = checkInput(kTstarInput, k.tstar); !e.empty()) return e;
    if (InputProblem e = checkInput(kAyRatioInput, c.ayRatio); !e.empty()) return e;
    if (InputProblem e = checkInput(kFyInput, c.fyHz); !e.empty()) return e;
    if (!(c.solver.relTol >= 1e-14 && c.solver.relTol <= 1e-2))
        return {"rel_tol", c.solver.relTol, "",
                "relative tolerance must be between 1e-14 and 1e-2"};
    if (!(c.solver.absTol > 0.0 && c.solver.absTol <= 1e-2))
        return {"abs_tol", c.solver.absTol, "", "absolute tolerance must be > 0 and at most 1e-2"};
    return {};
}

std::string validatePlanarCase(const PlanarCase& c) {
    return describe(checkPlanarCase(c));
}

namespace {
// One horizontal component. For the envelope-only normalization the amplitude handed to the
// enveloped sine (which divides by max(e sin)) is rescaled so that the factor is A / max(e).
std::shared_ptr<const Excitation1D> component(const PlanarCase& c, double amplitude, double f) {
    const Envelope& e = c.common.envelope;
    const double tstar = c.common.tstar;
    if (c.normalization == PlanarNormalization::Product)
        return std::make_shared<EnvelopedSine>(e, amplitude, f, tstar);
    const EnvelopedSine unit(e, 1.0, f, tstar);
    const double peak = unit.envelopePeakTau();
    const double envelopeMax = std::isfinite(peak) ? unit.envelopeAt(peak) : 1.0;
    return std::make_shared<EnvelopedSine>(e, amplitude * unit.sMax() / envelopeMax, f, tstar);
}
} // namespace

SlabModel2D planarModel(const PlanarCase& c, double ax, double fxHz) {
    auto x = component(c, ax, fxHz);
    std::shared_ptr<const Excitation1D> y;
    if (c.ayRatio > 0.0 && ax > 0.0) y = component(c, c.ayRatio * ax, c.fyHz);
    return SlabModel2D(std::move(x), std::move(y), c.vertical, c.params());
}

PlanarResult runPlanar(const PlanarCase& c, double ax, double fxHz, PlanarRecorder* recorder) {
    return solvePlanar(planarModel(c, ax, fxHz), c.solver, recorder);
}

PointFunction planarPoint(const PlanarCase& c) {
    return [c](double amplitude, double frequency) {
        const PlanarResult r = runPlanar(c, amplitude, frequency);
        return PointResult{r.slab.outcome, r.slab.tauC, r.exitSide};
    };
}

double planarNoSlipAmplitude(const PlanarCase& c) {
    const double nMin = c.vertical ? 1.0 - c.vertical->peak() : 1.0;
    return std::max(0.0, c.common.slab.mu * nMin / std::hypot(1.0, c.ayRatio));
}

} // namespace kinstab
