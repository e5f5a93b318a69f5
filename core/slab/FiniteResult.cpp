// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/slab/FiniteResult.h"

#include "core/base/InternalError.h"

#include <cmath>
#include <sstream>

namespace kinstab {

namespace {
std::string named(const std::string& field, double value) {
    std::ostringstream s;
    s << field << " = " << value;
    return s.str();
}
} // namespace

std::string nonFiniteField(const SlabResult& r) {
    if (r.outcome == Outcome::Collapsed && !std::isfinite(r.tauC)) return named("tau_c", r.tauC);
    if (r.outcome == Outcome::LiftOff && !std::isfinite(r.tauC))
        return named("tau_lift_off", r.tauC);
    if (!std::isfinite(r.tauEnd)) return named("tau_end", r.tauEnd);
    if (!std::isfinite(r.residualDelta)) return named("residual_delta", r.residualDelta);
    if (!std::isfinite(r.maxAbsDelta)) return named("max_abs_delta", r.maxAbsDelta);
    return {};
}

std::string nonFiniteField(const std::vector<SlabEvent>& events) {
    for (std::size_t i = 0; i < events.size(); ++i) {
        const SlabEvent& e = events[i];
        const std::string at = "event " + std::to_string(i) + " (" + eventKindName(e.kind) + ") ";
        if (!std::isfinite(e.tau)) return named(at + "tau", e.tau);
        if (!std::isfinite(e.delta)) return named(at + "delta", e.delta);
        if (!std::isfinite(e.velocity)) return named(at + "velocity", e.velocity);
    }
    return {};
}

void failIfNonFinite(SlabResult& r, const std::vector<SlabEvent>& events) {
    std::string field = nonFiniteField(r);
    if (field.empty()) field = nonFiniteField(events);
    if (field.empty()) return;
    r.failure = std::string(kInternalFailure) + "non-finite " + field + " (" +
                outcomeName(r.outcome) + " run)";
    r.outcome = Outcome::Failed;
}

bool isInternalFailure(const SlabResult& r) {
    return r.outcome == Outcome::Failed && r.failure.rfind(kInternalFailure, 0) == 0;
}

void requireSound(const SlabResult& r, const std::string& caseName) {
    if (isInternalFailure(r))
        throw InternalError(caseName + ": " +
                            r.failure.substr(std::string(kInternalFailure).size()));
    const std::string field = nonFiniteField(r);
    if (!field.empty()) throw InternalError(caseName + ": non-finite " + field);
}

} // namespace kinstab
