// SPDX-License-Identifier: GPL-3.0-or-later
#include "python/src/SlabCaseArguments.h"

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"
#include "python/src/Arguments.h"

#include <cmath>

namespace kinstab::python {

Envelope customEnvelope(double alpha, double beta) {
    finite("alpha", alpha);
    finite("beta", beta);
    const std::string e = validateEnvelope(alpha, beta);
    if (!e.empty()) badArgument("alpha/beta: " + e);
    return Envelope{alpha, beta, std::nullopt};
}

Envelope presetEnvelope(const std::string& name) {
    return Envelope::fromPreset(*presetFromName(choice("envelope", name, "fast|moderate|slow")));
}

Slab1DCase slabCaseFrom(const SlabCaseArguments& a) {
    if (a.tstar) finite("tstar", *a.tstar);
    if (a.wallWidthIn) finite("wall_width_in", *a.wallWidthIn);
    finite("mu", a.mu);
    finite("limit", a.limit);
    if (a.duration) finite("duration", *a.duration);
    finite("paper_steps", a.paperSteps);
    Slab1DCase c;
    c.envelope = a.envelope;
    if (a.tstar && a.wallWidthIn) badArgument("tstar and wall_width_in exclude each other");
    if (a.wallWidthIn) {
        const double d = *a.wallWidthIn;
        if (!(d > 0.0 && d <= limits::kMaxWallWidthIn))
            badArgument("wall_width_in", d,
                        "must be > 0 and at most " + formatDouble(limits::kMaxWallWidthIn));
        c.tstar = tstarFromWallWidthInches(d);
    } else {
        c.tstar = a.tstar.value_or(0.099);
        if (!(c.tstar > 0.0 && c.tstar <= 100.0))
            badArgument("tstar", c.tstar, "must be > 0 and at most 100 s");
    }
    c.slab.mu = a.mu;
    if (!(a.mu >= 0.0 && a.mu <= 10.0))
        badArgument("mu", a.mu, "friction coefficient must be between 0 and 10");
    c.slab.limit = a.limit;
    if (!(a.limit > 0.0 && a.limit <= 1e6)) badArgument("limit", a.limit, "must be > 0");
    if (a.duration) {
        if (!(*a.duration > 0.0)) badArgument("duration", *a.duration, "must be > 0");
        c.slab.duration = *a.duration;
    }
    c.scale = *tauScaleFromName(choice("scale", a.scale, "one|tau_dur|tau_max|tau_rise"));
    c.solver = choice("solver", a.solver, "exact|paper") == "exact" ? SolverKind::Exact
                                                                    : SolverKind::Paper;
    c.paperStepsPerPeriod = a.paperSteps;
    if (!(a.paperSteps >= 4.0 && a.paperSteps <= 1e6))
        badArgument("paper_steps", a.paperSteps, "must be between 4 and 1e6");
    return c;
}

} // namespace kinstab::python
