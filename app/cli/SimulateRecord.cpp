// kinstab-cli simulate --record FILE: the 1-DOF slab driven by a recorded motion (SPEC §3, §12),
// optionally through the floor filter and scaled to a target peak (--amplitude, g). The exact
// solver is exact for the linearly interpolated record; gamma_c uses the characteristic times
// of the envelope fitted to the driving motion (Fig. 27), or 1 with --scale one.

#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "app/cli/ModelFlags.h"
#include "app/cli/RecordFlags.h"
#include "core/excitation/EnvelopeFit.h"
#include "core/excitation/RecordedMotion.h"
#include "core/io/ResultJson.h"
#include "core/slab/ExactSolver.h"
#include "core/slab/History.h"

#include <chrono>
#include <iostream>

namespace kinstab::cli {

namespace {

void rejectSineFlags(const Args& args) {
    for (const char* f : {"frequency", "envelope", "alpha", "beta"})
        if (args.has(f))
            throw UsageError(std::string("--") + f + " " + args.text(f) +
                             ": describes the enveloped sine and does not apply with --record");
    if (args.has("solver") && args.text("solver") != "exact")
        throw UsageError("--solver " + args.text("solver") +
                         ": only the exact solver runs recorded motions");
}

// tau_ref for gamma_c from the envelope fitted to the driving motion; null when it cannot be
// fitted.
std::optional<double> recordTauRef(const Accelerogram& motion, const Slab1DCase& c,
                                   nlohmann::json& fitJson) {
    if (c.scale == TauScale::One) return 1.0;
    try {
        const EnvelopeFit fit = fitEnvelope(motion);
        const Envelope e{fit.alpha, fit.beta, std::nullopt};
        fitJson = {{"alpha", fit.alpha}, {"beta", fit.beta},     {"scale_g", fit.scale},
                   {"rms_g", fit.rms},   {"peak_g", fit.peak()}, {"peak_time_s", fit.peakTime()}};
        return e.tauRef(c.scale, c.tstar);
    } catch (const std::invalid_argument& e) {
        fitJson = {{"error", e.what()}};
        return std::nullopt;
    }
}

} // namespace

int runSimulateRecord(const Args& args) {
    rejectSineFlags(args);
    const Slab1DCase c = slab1DCaseFromFlags(args, true);
    const Accelerogram ground = readRecordFromFlag(args, "record");
    const std::optional<FloorFilterParams> filter = floorFilterFromFlags(args);
    const Accelerogram motion = filter ? floorMotion(ground, *filter) : ground;
    std::optional<double> target;
    if (args.has("amplitude")) {
        target = args.requiredNumber("amplitude");
        if (!(*target > 0.0) || *target > 1000.0)
            throw UsageError("--amplitude " + args.text("amplitude") +
                             ": target peak must be > 0 and at most 1000 g");
    }
    if (const std::string e = validateRecordedMotion(motion, c.tstar, target); !e.empty())
        throw UsageError("--record " + args.text("record") + ": " + e);
    const double historyStep = args.number("history-step", 0.05);
    if (historyStep <= 0.0)
        throw UsageError("--history-step " + args.text("history-step") + ": must be > 0");

    const auto t0 = std::chrono::steady_clock::now();
    const RecordedMotion a(motion, c.tstar, target);
    RunOptions options;
    options.recordEvents = args.has("history") || args.has("events");
    const SlabResult r = solveExact(a, c.slab, options);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    nlohmann::json fit;
    const std::optional<double> tauRef = recordTauRef(motion, c, fit);
    nlohmann::json j = slabResultJson(r, tauRef.value_or(std::nan("")));
    if (!tauRef) j["gamma_c"] = nullptr;
    j["model"] = "slab1d";
    j["solver"] = "exact";
    j["record"] = accelerogramJson(ground);
    j["floor_filter"] = filter ? floorFilterJson(*filter) : nlohmann::json(nullptr);
    j["amplitude"] = a.peak();
    j["scale_factor"] = a.scale();
    j["mu"] = c.slab.mu;
    j["tstar"] = c.tstar;
    j["tau_ref"] = tauRef ? nlohmann::json(*tauRef) : nlohmann::json(nullptr);
    j["scale"] = tauScaleName(c.scale);
    j["envelope_fit"] = fit.is_null() ? nlohmann::json(nullptr) : fit;
    j["record_end_tau"] = a.endTau();
    j["wall_time_s"] = wall;
    if (args.has("events")) j["events"] = eventsJson(r.events);
    if (args.has("history"))
        writeOutput(args.text("history"),
                    historyCsv(sampleHistory(a, c.slab.mu, r.events, r.tauEnd, historyStep)));
    std::cout << j.dump(2) << "\n";
    return 0;
}

} // namespace kinstab::cli
