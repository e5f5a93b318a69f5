// SPDX-License-Identifier: GPL-3.0-or-later
// simulate and surface with --model planar (docs/user-guide.md "The command line"): the JSON of the
// 1-DOF model with keys added, never renamed: exit_side ("across" | "along", null unless
// collapsed), tau_lift_off, max_abs_delta_y, residual_delta_y, and the planar case.

#include "app/cli/AnalysisRuns.h"
#include "app/cli/Commands.h"
#include "app/cli/PlanarFlags.h"
#include "core/io/JsonText.h"
#include "core/io/ResultJson.h"
#include "core/io/SurfaceJson.h"
#include "core/sweep/SearchWork.h"

#include <chrono>
#include <iostream>
#include <sstream>

namespace kinstab::cli {

nlohmann::json planarEventsJson(const std::vector<PlanarEvent>& events) {
    nlohmann::json a = nlohmann::json::array();
    for (const auto& e : events)
        a.push_back({{"tau", e.tau},
                     {"kind", eventKindName(e.kind)},
                     {"dx", e.dx},
                     {"dy", e.dy},
                     {"ux", e.ux},
                     {"uy", e.uy}});
    return a;
}

PlanarCliLogs::PlanarCliLogs(const Args& args)
    : recorder(args.has("events") ? &events : nullptr, args.has("history") ? &path : nullptr) {}

// The computed path (every accepted step and event) with the excitation there.
std::string planarHistoryCsv(const SlabModel2D& m, const std::vector<PlanarSample>& path) {
    std::ostringstream s;
    s.precision(12);
    s << "tau,ax,ay,n,dx,dy,ux,uy,state\n";
    for (const PlanarSample& p : path) {
        const Vec2 a = m.accel(p.tau);
        s << p.tau << ',' << a.x << ',' << a.y << ',' << m.normal(p.tau) << ',' << p.dx << ','
          << p.dy << ',' << p.ux << ',' << p.uy << ',' << (p.slipping ? "slip" : "stick") << '\n';
    }
    return s.str();
}

void addPlanarResultKeys(nlohmann::json& j, const PlanarResult& r) {
    j["exit_side"] = r.slab.outcome == Outcome::Collapsed ? nlohmann::json(exitSideName(r.exitSide))
                                                          : nlohmann::json();
    j["tau_lift_off"] = numberOrNull(r.tauLiftOff);
    j["max_abs_delta_y"] = r.maxAbsDeltaY;
    j["residual_delta_y"] = r.residualDeltaY;
    j["work"]["rejected_steps"] = r.slab.work.restarts;
}

int runSimulatePlanar(const Args& args, double amplitude, double frequency, double historyStep) {
    PlanarCase c = planarCaseFromFlags(args);
    if (args.has("history-step") && historyStep > 0.0)
        throw UsageError("--history-step: with --model planar the history lists the solver's own "
                         "steps and events");
    if (const InputProblem p = checkPlanarRunWork(c, amplitude, frequency); !p.empty())
        throw UsageError("--frequency " + args.text("frequency") + ": " + p.why);
    const SlabModel2D model = planarModel(c, amplitude, frequency);
    const auto t0 = std::chrono::steady_clock::now();
    PlanarCliLogs log(args);
    const PlanarResult r = solvePlanar(model, c.solver, &log.recorder);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    nlohmann::json j = slabResultJson(r.slab, c.tauRef());
    j.update(planarCaseJson(c));
    j["amplitude"] = amplitude;
    j["frequency"] = frequency;
    j["tau_ref"] = c.tauRef();
    addPlanarResultKeys(j, r);
    j["wall_time_s"] = wall;
    if (args.has("events")) j["events"] = planarEventsJson(log.events.events);
    if (args.has("history")) writeOutput(args, "history", planarHistoryCsv(model, log.path.path));
    std::cout << jsonText(j, 2) << "\n";
    return 0;
}

int runSurfacePlanar(const Args& args, const SweepGrid& grid, int threads,
                     const std::string& format) {
    const PlanarCase c = planarCaseFromFlags(args);
    AnalysisRequest request;
    request.planar = c;
    const SweepResult r = surfaceOf(request, grid, threads);
    if (format == "csv") {
        writeOutput(args, "o", sweepCsv(r, c.tauRef()));
        return 0;
    }
    writeOutput(args, "o", jsonText(surfaceJson(r, c)) + "\n");
    return 0;
}

// A_crit(f_x) of the planar model. The scan starts where anything can slip at all:
// A_x sqrt(1 + ratio^2) = mu min n, below mu itself (both components push).
int runCriticalPlanar(const Args& args, const std::vector<double>& frequencies,
                      const CriticalSearch& search) {
    const PlanarCase c = planarCaseFromFlags(args);
    AnalysisRequest request;
    request.planar = c;
    request.criticalFrequencies = frequencies;
    request.criticalSearch = search;
    const nlohmann::json crit = criticalCurveJson(request);
    nlohmann::json j = planarCaseJson(c);
    j.update({{"frequencies", frequencies},
              {"a_crit", crit},
              {"max_amplitude", search.to},
              {"scan_step", search.scanStep},
              {"tolerance", search.tolerance}});
    std::cout << jsonText(j, 2) << "\n";
    return 0;
}

} // namespace kinstab::cli
