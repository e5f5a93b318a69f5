// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/CaseJson.h"

#include "core/base/ModelKind.h"
#include "core/excitation/RecordedMotion.h"

namespace kinstab {

nlohmann::json envelopeJson(const Slab1DCase& c) {
    const CharacteristicTimes computed = c.envelope.computedTimes(c.tstar);
    const CharacteristicTimes used = c.envelope.scalingTimes(c.tstar);
    nlohmann::json j = {{"name", c.envelope.name()},
                        {"alpha", c.envelope.alpha},
                        {"beta", c.envelope.beta},
                        {"tau_rise", used.tauRise},
                        {"tau_max", used.tauMax},
                        {"tau_dur", used.tauDur},
                        {"computed",
                         {{"tau_rise", computed.tauRise},
                          {"tau_max", computed.tauMax},
                          {"tau_dur", computed.tauDur}}},
                        {"scale", tauScaleName(c.scale)}};
    return j;
}

nlohmann::json slab1DCaseJson(const Slab1DCase& c) {
    return {{"model", modelKindName(ModelKind::Slab1D)},
            {"solver", solverName(c.solver)},
            {"envelope", envelopeJson(c)},
            {"mu", c.slab.mu},
            {"tstar", c.tstar},
            {"limit", c.slab.limit}};
}

nlohmann::json planarCaseJson(const PlanarCase& c) {
    nlohmann::json vertical; // null: gravity only
    if (const auto* r = dynamic_cast<const RecordedMotion*>(c.vertical.get()))
        vertical = {
            {"samples", r->samples().size()}, {"dt_tau", r->sampleStep()}, {"peak_g", r->peak()}};
    return {{"model", modelKindName(ModelKind::Planar)},
            {"solver", "dop853"},
            {"rel_tol", c.solver.relTol},
            {"abs_tol", c.solver.absTol},
            {"envelope", envelopeJson(c.common)},
            {"mu", c.common.slab.mu},
            {"tstar", c.common.tstar},
            {"limit", c.common.slab.limit},
            {"theta", c.theta},
            {"ay_ratio", c.ayRatio},
            {"fy", c.fyHz},
            {"normalization", normalizationName(c.normalization)},
            {"vertical", vertical}};
}

} // namespace kinstab
