// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/ModelFlags.h"

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"

namespace kinstab::cli {

std::set<std::string> modelFlagNames() {
    return {"model", "envelope", "alpha",  "beta",         "tstar",       "wall-width-in", "mu",
            "limit", "scale",    "solver", "duration",     "paper-steps", "ay-ratio",      "fy",
            "theta", "vertical", "record", "floor-period", "damping",     "normalization"};
}

ModelKind modelFromFlags(const Args& args) {
    std::set<std::string> names;
    for (ModelKind m : kModelKinds)
        names.insert(modelKindName(m));
    return *modelKindFromName(args.choice("model", names, modelKindName(ModelKind::Slab1D)));
}

namespace {
void requireOnly1D(const Args& args, bool allowRecord) {
    if (modelFromFlags(args) != ModelKind::Slab1D)
        throw UsageError(
            "--model planar: not available for this command (use simulate or surface)");
    for (const char* f : {"ay-ratio", "fy", "theta", "vertical", "normalization"})
        if (args.has(f))
            throw UsageError(std::string("--") + f + " applies to --model planar only");
    for (const char* f : {"record", "floor-period", "damping"})
        if (args.has(f) && !allowRecord)
            throw UsageError(std::string("--") + f + " " + args.text(f) +
                             ": recorded motions run with 'simulate --record FILE' only");
}
} // namespace

Slab1DCase slab1DCaseFromFlags(const Args& args, bool allowRecord) {
    requireOnly1D(args, allowRecord);
    return commonCaseFromFlags(args);
}

Slab1DCase commonCaseFromFlags(const Args& args) {
    Slab1DCase c;
    const bool custom = args.has("alpha") || args.has("beta");
    if (custom) {
        if (args.has("envelope"))
            throw UsageError("--envelope and --alpha/--beta exclude each other");
        c.envelope =
            Envelope{args.requiredNumber("alpha"), args.requiredNumber("beta"), std::nullopt};
        const std::string e = validateEnvelope(c.envelope.alpha, c.envelope.beta);
        if (!e.empty()) throw UsageError("--alpha/--beta: " + e);
    } else {
        const std::string name = args.choice("envelope", {"fast", "moderate", "slow"}, "moderate");
        c.envelope = Envelope::fromPreset(*presetFromName(name));
    }
    if (args.has("tstar") && args.has("wall-width-in"))
        throw UsageError("--tstar and --wall-width-in exclude each other");
    if (args.has("wall-width-in")) {
        const double d = args.requiredNumber("wall-width-in");
        if (d <= 0.0 || d > limits::kMaxWallWidthIn)
            throw UsageError("--wall-width-in " + args.text("wall-width-in") +
                             ": must be > 0 and at most " + formatDouble(limits::kMaxWallWidthIn));
        c.tstar = tstarFromWallWidthInches(d);
    } else {
        c.tstar = args.number("tstar", 0.099);
        if (c.tstar <= 0.0 || c.tstar > 100.0)
            throw UsageError("--tstar " + args.text("tstar") + ": must be > 0 and at most 100 s");
    }
    c.slab.mu = args.number("mu", 0.6);
    if (c.slab.mu < 0.0 || c.slab.mu > 10.0)
        throw UsageError("--mu " + args.text("mu") +
                         ": friction coefficient must be between 0 and 10");
    c.slab.limit = args.number("limit", 1.0);
    if (c.slab.limit <= 0.0 || c.slab.limit > 1e6)
        throw UsageError("--limit " + args.text("limit") + ": must be > 0");
    if (const auto d = args.optionalNumber("duration")) {
        if (*d <= 0.0) throw UsageError("--duration " + args.text("duration") + ": must be > 0");
        c.slab.duration = *d;
    }
    c.scale = *tauScaleFromName(
        args.choice("scale", {"tau_max", "tau_rise", "tau_dur", "one"}, "tau_max"));
    c.solver = args.choice("solver", {"exact", "paper"}, "exact") == "exact" ? SolverKind::Exact
                                                                             : SolverKind::Paper;
    c.paperStepsPerPeriod = args.number("paper-steps", 16);
    if (c.paperStepsPerPeriod < 4.0 || c.paperStepsPerPeriod > 1e6)
        throw UsageError("--paper-steps " + args.text("paper-steps") +
                         ": must be between 4 and 1e6");
    return c;
}

} // namespace kinstab::cli
