// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli rocking: one run of a free-standing block (rest, slide, rock, slide-rock,
// overturning; core/rocking/RockingSolver.h) under a pulse, the paper's enveloped sine, a record
// (optionally the floor motion of a level of the project's building), or free rocking from a
// tilt; with --critical the smallest overturning amplitude and the overturning intervals.

#include "app/cli/Args.h"
#include "app/cli/BuildingFlags.h"
#include "app/cli/Commands.h"
#include "app/cli/RecordFlags.h"
#include "app/cli/RockingFlags.h"
#include "core/base/InputError.h"
#include "core/excitation/EnvelopedSine.h"
#include "core/io/AtomicFile.h"
#include "core/io/JsonText.h"
#include "core/io/RockingJson.h"
#include "core/rocking/OverturningAmplitude.h"
#include "core/rocking/RockingMotions.h"
#include "core/rocking/RockingSolver.h"

#include <chrono>
#include <cstdio>
#include <memory>
#include <sstream>

namespace kinstab::cli {

namespace {

struct RockingExcitation {
    std::unique_ptr<BaseMotion> motion = std::make_unique<NoMotion>();
    MotionFamily family; // empty: nothing to scale (free rocking)
    nlohmann::json json = {{"kind", "none"}};
};

Pulse pulseFromFlags(const Args& args) {
    Pulse p;
    const std::string name =
        args.choice("pulse", {"half-sine", "one-sine", "one-cosine", "rectangular"}, "half-sine");
    p.shape = *pulseShapeFromName(name);
    if (!args.has("amplitude")) throw UsageError("--pulse " + name + ": needs --amplitude A_G");
    p.amplitude = args.input(kPulseAmplitudeInput);
    if (p.shape == PulseShape::Rectangular) {
        if (args.has("pulse-frequency"))
            throw UsageError("--pulse-frequency " + args.text("pulse-frequency") +
                             ": a rectangular pulse takes --pulse-duration S");
        if (!args.has("pulse-duration"))
            throw UsageError("--pulse rectangular: needs --pulse-duration S");
        p.durationS = args.input(kPulseDurationInput);
    } else {
        if (args.has("pulse-duration"))
            throw UsageError("--pulse-duration " + args.text("pulse-duration") +
                             ": only a rectangular pulse has one (--pulse-frequency F)");
        if (!args.has("pulse-frequency"))
            throw UsageError("--pulse " + name + ": needs --pulse-frequency F (Hz)");
        p.frequencyHz = args.input(kPulseFrequencyInput);
    }
    args.refuse(checkPulse(p));
    return p;
}

RockingExcitation pulseExcitation(const Args& args) {
    const Pulse p = pulseFromFlags(args);
    RockingExcitation e;
    e.motion = std::make_unique<PulseMotion>(p);
    e.family = pulseFamily(p);
    e.json = pulseExcitationJson(p);
    return e;
}

RockingExcitation sineExcitation(const Args& args, std::optional<double> duration) {
    const bool custom = args.has("alpha") || args.has("beta");
    Envelope env;
    if (custom) {
        if (args.has("envelope"))
            throw UsageError("--envelope and --alpha/--beta exclude each other");
        env = Envelope{args.requiredNumber("alpha"), args.requiredNumber("beta"), std::nullopt};
        args.refuse(checkEnvelope(env.alpha, env.beta));
    } else {
        env = Envelope::fromPreset(
            *presetFromName(args.choice("envelope", {"fast", "moderate", "slow"}, "moderate")));
    }
    if (!args.has("amplitude")) throw UsageError("--frequency: needs --amplitude A_G");
    const double amplitude = args.input(kAmplitudeInput);
    const double frequency = args.input(kFrequencyInput);
    RockingExcitation e;
    e.motion = envelopedSineMotion(env, amplitude, frequency, duration);
    e.family = [env, frequency, duration](double a) {
        return envelopedSineMotion(env, a, frequency, duration);
    };
    e.json = sineExcitationJson(env, amplitude, frequency, e.motion->end());
    return e;
}

// The driving record: the file through the floor filter, or the floor motion of --level of the
// project's building; scaled to --amplitude or by --scale-factor.
RockingExcitation recordExcitation(const Args& args) {
    const RecordExcitation rec = recordExcitationFromFlags(args, "record");
    Accelerogram motion;
    try {
        const Accelerogram ground = readGroundRecord(rec);
        motion = drivingMotion(rec, ground);
        if (args.has("level")) {
            if (rec.floor) throw UsageError("--level and --floor-period exclude each other");
            if (!args.has("project"))
                throw UsageError("--level: needs --project FILE (the building)");
            const Project p = projectFromFlag(args);
            const FloorSettings s = p.floors.value_or(FloorSettings{});
            motion =
                levelMotion(p.building, s.stiffness, s.damping, args.integer("level", 0), ground);
        }
    } catch (const RecordError& e) {
        throw UsageError("--record " + rec.file + ": " + e.what());
    } catch (const InputError& e) {
        throw inputUsageError(e);
    } catch (const std::invalid_argument& e) {
        throw UsageError((args.has("level") ? "--level " + args.text("level") + ": " : "") +
                         e.what());
    }
    std::optional<Accelerogram> vertical;
    if (args.has("vertical")) vertical = readRecordFromFlag(args, "vertical");
    const double peak = scaledPeak(rec, motion);
    RockingExcitation e;
    try {
        e.motion = recordMotion(motion, peak, vertical ? &*vertical : nullptr);
    } catch (const std::invalid_argument& x) {
        throw UsageError("--record " + rec.file + ": " + x.what());
    }
    e.family = recordFamily(motion, vertical);
    const std::optional<int> level =
        args.has("level") ? std::optional<int>(args.integer("level", 0)) : std::nullopt;
    e.json = recordExcitationJson(motion, peak, level, vertical ? &*vertical : nullptr);
    return e;
}

RockingExcitation excitationFromFlags(const Args& args, const RockingModel& m) {
    const int kinds = args.has("pulse") + args.has("frequency") + args.has("record");
    if (kinds > 1)
        throw UsageError("--pulse, --frequency (enveloped sine) and --record exclude each other");
    if (args.has("pulse")) return pulseExcitation(args);
    if (args.has("frequency")) return sineExcitation(args, m.duration);
    if (args.has("record")) return recordExcitation(args);
    for (const char* f : {"amplitude", "pulse-frequency", "pulse-duration", "vertical", "level"})
        if (args.has(f))
            throw UsageError(std::string("--") + f + " " + args.text(f) +
                             ": needs an excitation (--pulse, --frequency or --record)");
    if (!(m.initialTilt > 0.0))
        throw UsageError("no excitation: give --pulse SHAPE, --frequency F (enveloped sine), "
                         "--record FILE, or --initial-tilt R for free rocking");
    return {};
}

std::string historyCsv(const std::vector<RockingSample>& h, const BaseMotion& motion,
                       double alpha) {
    std::ostringstream s;
    s.imbue(std::locale::classic());
    s.precision(10);
    s << "t_s,theta_rad,theta_over_alpha,omega_rad_s,sliding_m,mode,a_h_g\n";
    for (const RockingSample& x : h)
        s << x.t << ',' << x.theta << ',' << x.theta / alpha << ',' << x.omega << ',' << x.sliding
          << ',' << blockModeName(x.mode) << ',' << motion.horizontal(x.t) << '\n';
    return s.str();
}

// The search's settings from the flags: the scan, the refinement near overturning and the run
// budget (core/rocking/OverturningAmplitude.h).
OverturningSearch searchFromFlags(const Args& args) {
    OverturningSearch s;
    s.maxAmplitude = args.number("max-amplitude", 5.0);
    if (!(s.maxAmplitude > 0.0 && s.maxAmplitude <= limits::kMaxAmplitudeG))
        throw UsageError("--max-amplitude " + args.text("max-amplitude") +
                         ": must be > 0 and at most 1000 g");
    s.scanPoints = args.integer("scan-points", 200);
    if (s.scanPoints < 2 || s.scanPoints > 100000)
        throw UsageError("--scan-points " + args.text("scan-points") + ": must be 2 to 100000");
    s.tolerance = args.number("tolerance", 1e-4);
    if (!(s.tolerance >= 1e-12 && s.tolerance <= 0.1))
        throw UsageError("--tolerance " + args.text("tolerance") + ": must be 1e-12 to 0.1");
    s.refineDepth = args.integer("refine-depth", kOverturningRefineDepth);
    if (s.refineDepth < 0 || s.refineDepth > 20)
        throw UsageError("--refine-depth " + args.text("refine-depth") + ": must be 0 to 20");
    s.maxRuns = args.integer("max-runs", static_cast<int>(kOverturningMaxRuns));
    if (s.maxRuns < 10 || s.maxRuns > 10000000)
        throw UsageError("--max-runs " + args.text("max-runs") + ": must be 10 to 10000000");
    return s;
}

nlohmann::json criticalJson(const RockingModel& m, const RockingExcitation& e, const Args& args) {
    if (!e.family)
        throw UsageError("--critical: needs an excitation to scale (--pulse, "
                         "--frequency or --record)");
    const OverturningSearch s = searchFromFlags(args);
    const OverturningIntervals iv = overturningIntervals(m, e.family, s);
    if (iv.runLimitReached)
        std::fprintf(stderr,
                     "kinstab-cli rocking: --critical stopped at its limit of %ld runs "
                     "(--max-runs): gaps near overturning were not all refined or bisected\n",
                     s.maxRuns);
    return overturningSearchJson(iv, s);
}

} // namespace

int runRocking(const ArgList& argv) {
    std::set<std::string> flags = rockingModelFlagNames();
    flags.merge(recordReadFlagNames());
    flags.insert({"pulse",         "pulse-frequency", "pulse-duration", "amplitude", "frequency",
                  "envelope",      "alpha",           "beta",           "record",    "scale-factor",
                  "floor-period",  "damping",         "vertical",       "project",   "level",
                  "max-amplitude", "scan-points",     "tolerance",      "history",   "history-step",
                  "refine-depth",  "max-runs"});
    const Args args(argv, flags, {"linear", "critical"});
    const RockingModel m = rockingModelFromFlags(args);
    if (args.has("history")) checkOutputPath("history", args.text("history"));
    for (const char* f : {"max-amplitude", "scan-points", "tolerance", "refine-depth", "max-runs"})
        if (args.has(f) && !args.has("critical"))
            throw UsageError(std::string("--") + f + " " + args.text(f) + ": needs --critical");
    const auto start = std::chrono::steady_clock::now();
    const RockingExcitation e = excitationFromFlags(args, m);
    RockingRunOptions o;
    std::vector<RockingSample> history;
    if (args.has("history")) {
        o.sampleInterval = args.number("history-step", 0.01);
        if (!(o.sampleInterval >= 1e-5 && o.sampleInterval <= 10.0))
            throw UsageError("--history-step " + args.text("history-step") +
                             ": must be 1e-5 to 10 s");
        o.recorder = [&history](const RockingSample& s) { history.push_back(s); };
    }
    const RockingResult r = simulateRocking(m, *e.motion, o);
    nlohmann::json j = rockingResultJson(r);
    j["block"] = rockingModelJson(m);
    j["excitation"] = e.json;
    if (args.has("critical")) j.update(criticalJson(m, e, args));
    j["wall_time_s"] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (args.has("history"))
        writeOutput(args, "history", historyCsv(history, *e.motion, blockAlpha(m.block)));
    writeStandardOutput(jsonText(j, 2) + "\n");
    return 0;
}

} // namespace kinstab::cli
