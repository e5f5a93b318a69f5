// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "app/cli/ModelFlags.h"
#include "app/cli/PlanarFlags.h"
#include "app/cli/RecordFlags.h"
#include "app/cli/SearchFlags.h"
#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"
#include "core/excitation/EnvelopedSine.h"
#include "core/excitation/FrequencyRange.h"
#include "core/io/JsonText.h"
#include "core/io/ResultJson.h"
#include "core/slab/FiniteResult.h"
#include "core/slab/History.h"
#include "core/slab/SlabRecorder.h"
#include "core/sweep/SearchWork.h"

#include <chrono>
#include <iostream>
#include <sstream>

namespace kinstab::cli {

namespace {

// --record's flags: the record reader's and --critical's search.
std::set<std::string> recordOnlyFlags() {
    std::set<std::string> recordFlags = recordReadFlagNames();
    recordFlags.merge(searchFlagNames()); // --critical's search, with --record only
    return recordFlags;
}

// The 1-DOF slab under an enveloped sine: the result as JSON, --events, --history.
int runSimulateSlab1D(const Args& args, double amplitude, double frequency, double historyStep) {
    const bool wantHistory = args.has("history");
    const Slab1DCase c = slab1DCaseFromFlags(args);
    if (const InputProblem p = checkRunWork(c, amplitude, {frequency, 1.0, solverCostFactor(c)});
        !p.empty())
        throw UsageError("--frequency " + args.text("frequency") + ": " + p.why);
    // The events for --events, and the history sampled from them for --history.
    const EnvelopedSine a(c.envelope, amplitude, frequency, c.tstar);
    SlabHistoryLog log(a, c.slab.mu);
    SlabRecorder* recorder = wantHistory || args.has("events") ? &log : nullptr;
    const auto t0 = std::chrono::steady_clock::now();
    const SlabResult r = runSlab1D(c, amplitude, frequency, {}, recorder);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    requireSound(r, caseName(c, amplitude, frequency));

    nlohmann::json j = slabResultJson(r, c.tauRef());
    j["model"] = modelKindName(ModelKind::Slab1D);
    j["solver"] = solverName(c.solver);
    j["amplitude"] = amplitude;
    j["frequency"] = frequency;
    j["mu"] = c.slab.mu;
    j["tstar"] = c.tstar;
    j["tau_ref"] = c.tauRef();
    j["envelope"] = envelopeJson(c);
    j["wall_time_s"] = wall;
    if (args.has("events")) j["events"] = eventsJson(log.events);
    if (wantHistory) {
        if (const std::string e = validateHistoryStep(r.tauEnd, historyStep); !e.empty())
            throw UsageError("--history-step " + args.text("history-step", "0.05") + ": " + e);
        writeOutput(args, "history", historyCsv(log.history(r.tauEnd, historyStep)));
    }
    std::cout << jsonText(j, 2) << "\n";
    return 0;
}

} // namespace

int runSimulate(const ArgList& argv) {
    std::set<std::string> flags = modelFlagNames();
    flags.insert({"amplitude", "frequency", "history", "history-step", "scale-factor", "record-y"});
    std::set<std::string> recordFlags = recordOnlyFlags();
    flags.insert(recordFlags.begin(), recordFlags.end());
    const Args args(argv, flags, {"events", "critical"});
    if (args.has("record") && !isPlanar(args)) return runSimulateRecord(args);
    if (args.has("record")) return runSimulatePlanarRecord(args);
    recordFlags.insert({"scale-factor", "record-y"});
    for (const std::string& f : recordFlags)
        if (args.has(f)) throw UsageError("--" + f + " " + args.text(f) + ": needs --record FILE");
    if (args.has("critical")) throw UsageError("--critical: needs --record FILE");
    args.requiredNumber("amplitude");
    args.requiredNumber("frequency");
    const double amplitude = args.input(kAmplitudeInput);
    const double frequency = args.input(kFrequencyInput);
    const double historyStep = args.number("history-step", 0.05);
    if (historyStep <= 0.0)
        throw UsageError("--history-step " + args.text("history-step") + ": must be > 0");
    if (isPlanar(args)) return runSimulatePlanar(args, amplitude, frequency, historyStep);
    return runSimulateSlab1D(args, amplitude, frequency, historyStep);
}

} // namespace kinstab::cli
