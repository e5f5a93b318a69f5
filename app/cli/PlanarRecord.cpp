// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli simulate --model planar --record FILE [--record-y FILE] (docs/theory.md §5, §7;
// docs/user-guide.md "The command line"): the planar slab with a_x from the record (scaled by
// --amplitude PEAK_G or --scale-factor F) and a_y from a second component scaled by the same factor
// (none: no motion along the walls), both through the floor filter when --floor-period is given,
// and the vertical --vertical FILE as for the sine. The JSON is simulate's planar object with the
// record keys of simulate --record.

#include "app/cli/Commands.h"
#include "app/cli/PlanarFlags.h"
#include "app/cli/RecordFlags.h"
#include "core/check/RecordAnalysis.h"
#include "core/io/JsonText.h"
#include "core/io/JsonValue.h"
#include "core/io/PlanarResultJson.h"
#include "core/slab/PlanarRecordCase.h"

#include <chrono>
#include <iostream>

namespace kinstab::cli {

namespace {

void rejectSineFlags(const Args& args) {
    for (const char* f : {"frequency", "envelope", "alpha", "beta", "ay-ratio", "fy",
                          "normalization", "critical", "history-step"})
        if (args.has(f))
            throw UsageError(std::string("--") + f + " " + args.text(f) +
                             ": does not apply to --model planar --record");
}

} // namespace

int runSimulatePlanarRecord(const Args& args) {
    rejectSineFlags(args);
    PlanarCase c = planarCaseFromFlags(args, true);
    const RecordExcitation e = recordExcitationFromFlags(args, "record");
    PlanarRecordMotions m;
    const Accelerogram groundX = readRecordFromFlag(args, "record");
    std::optional<Accelerogram> groundY;
    if (args.has("record-y")) groundY = readRecordFromFlag(args, "record-y");
    m.x = drivingMotion(e, groundX);
    if (groundY) m.y = drivingMotion(e, *groundY);
    m.peakX = scaledPeak(e, m.x);
    if (const std::string err = validatePlanarRecordMotions(m, c.common.tstar); !err.empty())
        throw UsageError(std::string(err.rfind("y", 0) == 0 ? "--record-y " : "--record ") +
                         args.text(err.rfind("y", 0) == 0 ? "record-y" : "record") + ": " + err);
    const SlabModel2D model = planarRecordModel(c, m);
    const auto t0 = std::chrono::steady_clock::now();
    PlanarCliLogs log(args);
    const PlanarResult r = solvePlanar(model, c.solver, &log.recorder);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    const std::optional<double> tauRef = recordTauRef(fitOrNone(m.x), c.common);
    nlohmann::json j = planarResultJson(r, tauRef.value_or(std::nan("")));
    if (!tauRef) j["gamma_c"] = nullptr;
    j.update(planarCaseJson(c));
    for (const char* k : {"envelope", "ay_ratio", "fy", "normalization"})
        j.erase(k); // the sine's parameters: the records replace them
    j["record"] = accelerogramJson(groundX);
    j["record_y"] = groundY ? accelerogramJson(*groundY) : nlohmann::json();
    j["floor_filter"] = e.floor ? floorFilterJson(*e.floor) : nlohmann::json();
    j["amplitude"] = m.peakX;
    j["scale_factor"] = m.peakX / std::abs(m.x.peak().value);
    j["tau_ref"] = orNull(tauRef);
    j["wall_time_s"] = wall;
    if (args.has("events")) j["events"] = planarEventsJson(log.events.events);
    if (args.has("history")) writeOutput(args, "history", planarHistoryCsv(model, log.path.path));
    std::cout << jsonText(j, 2) << "\n";
    return 0;
}

} // namespace kinstab::cli
