// SPDX-License-Identifier: GPL-3.0-or-later
#include "python/src/SlabCaseArguments.h"

#include "core/slab/SlabInputs.h"
#include "python/src/Arguments.h"

namespace kinstab::python {

Envelope customEnvelope(double alpha, double beta) {
    refuse(checkEnvelope(alpha, beta));
    return Envelope{alpha, beta, std::nullopt};
}

Envelope presetEnvelope(const std::string& name) {
    return Envelope::fromPreset(*presetFromName(choice("envelope", name, "fast|moderate|slow")));
}

Slab1DCase slabCaseFrom(const SlabCaseArguments& a) {
    if (a.tstar && a.wallWidthIn) badArgument("tstar and wall_width_in exclude each other");
    Slab1DCase c;
    c.envelope = a.envelope;
    c.tstar = a.wallWidthIn ? tstarFromWallWidthInches(keyword(kWallWidthInput, *a.wallWidthIn))
                            : keyword(kTstarInput, a.tstar.value_or(kTstarInput.fallback));
    c.slab.mu = keyword(kMuInput, a.mu);
    c.slab.limit = keyword(kLimitInput, a.limit);
    if (a.duration) c.slab.duration = keyword(kDurationInput, *a.duration);
    c.scale = *tauScaleFromName(choice("scale", a.scale, "one|tau_dur|tau_max|tau_rise"));
    c.solver = choice("solver", a.solver, "exact|paper") == "exact" ? SolverKind::Exact
                                                                    : SolverKind::Paper;
    c.paperStepsPerPeriod = keyword(kPaperStepsInput, a.paperSteps);
    refuse(checkCase(c)); // every rule is core's; this only names the keyword
    return c;
}

} // namespace kinstab::python
