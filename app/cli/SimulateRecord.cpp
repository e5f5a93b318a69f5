// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli simulate --record FILE: the 1-DOF slab driven by a recorded motion (docs/theory.md
// §3; docs/user-guide.md "The command line"), optionally through the floor filter and scaled to a
// target peak (--amplitude, g) or by a factor (--scale-factor). The exact solver is exact for the
// linearly interpolated record; gamma_c uses the characteristic times of the envelope fitted to the
// driving motion (Fig. 27), or 1 with --scale one. --critical adds the critical scale: the smallest
// peak (g) of the scaled motion that collapses the slab (--max-amplitude, --scan-step, --tolerance
// as for `critical`).

#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "app/cli/ModelFlags.h"
#include "app/cli/RecordFlags.h"
#include "app/cli/SearchFlags.h"
#include "core/check/RecordAnalysis.h"
#include "core/excitation/RecordedMotion.h"
#include "core/io/JsonText.h"
#include "core/io/ResultJson.h"
#include "core/slab/History.h"

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
    if (args.has("record-y"))
        throw UsageError("--record-y " + args.text("record-y") +
                         ": a second horizontal component needs --model planar");
    if (!args.has("critical"))
        for (const std::string& f : searchFlagNames())
            if (args.has(f)) throw UsageError("--" + f + " " + args.text(f) + ": needs --critical");
}

RecordAnalysis analyse(const Args& args, const RecordAnalysisInput& in, SlabRecorder* recorder) {
    try {
        return analyseRecord(in, nullptr, recorder);
    } catch (const RecordError& e) {
        throw UsageError("--record " + args.text("record") + ": " + e.what());
    } catch (const std::invalid_argument& e) {
        throw UsageError("--record " + args.text("record") + ": " + e.what());
    }
}

} // namespace

int runSimulateRecord(const Args& args) {
    rejectSineFlags(args);
    RecordAnalysisInput in;
    in.slab = slab1DCaseFromFlags(args, true);
    in.record = recordExcitationFromFlags(args, "record");
    in.critical = args.has("critical");
    if (in.critical) in.search = criticalSearchFromFlags(args);
    const double historyStep = args.number("history-step", 0.05);
    if (historyStep <= 0.0)
        throw UsageError("--history-step " + args.text("history-step") + ": must be > 0");

    // The single run's events, for --events and the --history sampled from them.
    SlabEventLog events;
    const bool keep = args.has("history") || args.has("events");
    const RecordAnalysis a = analyse(args, in, keep ? &events : nullptr);
    const Slab1DCase& c = in.slab;
    nlohmann::json j = slabResultJson(a.run, a.tauRef.value_or(std::nan("")));
    if (!a.tauRef) j["gamma_c"] = nullptr;
    j["model"] = modelKindName(ModelKind::Slab1D);
    j["solver"] = "exact";
    j["record"] = accelerogramJson(a.ground);
    j["floor_filter"] = in.record.floor ? floorFilterJson(*in.record.floor) : nlohmann::json();
    j["amplitude"] = a.peak;
    j["scale_factor"] = a.scaleFactor;
    j["mu"] = c.slab.mu;
    j["tstar"] = c.tstar;
    j["tau_ref"] = a.tauRef ? nlohmann::json(*a.tauRef) : nlohmann::json(nullptr);
    j["scale"] = tauScaleName(c.scale);
    j["envelope_fit"] = recordFitJson(a);
    const RecordedMotion motion(a.motion, c.tstar, a.peak);
    j["record_end_tau"] = motion.endTau();
    j["wall_time_s"] = a.runSeconds;
    if (in.critical) j["critical"] = recordCriticalJson(a, in.search);
    if (args.has("events")) j["events"] = eventsJson(events.events);
    if (args.has("history")) {
        if (const std::string e = validateHistoryStep(a.run.tauEnd, historyStep); !e.empty())
            throw UsageError("--history-step " + args.text("history-step", "0.05") + ": " + e);
        writeOutput(
            args, "history",
            historyCsv(sampleHistory(motion, c.slab.mu, events.events, a.run.tauEnd, historyStep)));
    }
    std::cout << jsonText(j, 2) << "\n";
    return 0;
}

} // namespace kinstab::cli
