// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/ModelFlags.h"

#include "core/slab/SlabInputs.h"

namespace kinstab::cli {

std::set<std::string> modelFlagNames() {
    return {"model",         "envelope", "alpha",        "beta",  "tstar",    "wall-width-in",
            "wall-width-mm", "mu",       "limit",        "scale", "solver",   "duration",
            "paper-steps",   "ay-ratio", "fy",           "theta", "vertical", "record",
            "floor-period",  "damping",  "normalization"};
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
        args.refuse(checkEnvelope(c.envelope.alpha, c.envelope.beta));
    } else {
        const std::string name = args.choice("envelope", {"fast", "moderate", "slow"}, "moderate");
        c.envelope = Envelope::fromPreset(*presetFromName(name));
    }
    // One of t*, the width in inches, the width in millimetres (exit 2 for two of them).
    const char* given[] = {"tstar", "wall-width-in", "wall-width-mm"};
    for (int i = 0; i < 3; ++i)
        for (int j = i + 1; j < 3; ++j)
            if (args.has(given[i]) && args.has(given[j]))
                throw UsageError(std::string("--") + given[i] + " and --" + given[j] +
                                 " exclude each other");
    if (const std::optional<double> mm = args.optionalInput(kWallWidthMmInput))
        c.tstar = tstarFromWallWidth(*mm / 1000.0);
    else if (const std::optional<double> in = args.optionalInput(kWallWidthInput))
        c.tstar = tstarFromWallWidthInches(*in);
    else
        c.tstar = args.input(kTstarInput);
    c.slab.mu = args.input(kMuInput);
    c.slab.limit = args.input(kLimitInput);
    c.slab.duration = args.optionalInput(kDurationInput);
    c.scale = *tauScaleFromName(
        args.choice("scale", {"tau_max", "tau_rise", "tau_dur", "one"}, "tau_max"));
    c.solver = args.choice("solver", {"exact", "paper"}, "exact") == "exact" ? SolverKind::Exact
                                                                             : SolverKind::Paper;
    c.paperStepsPerPeriod = args.input(kPaperStepsInput);
    args.refuse(checkCase(c)); // every rule is core's; this only names the flag
    return c;
}

} // namespace kinstab::cli
