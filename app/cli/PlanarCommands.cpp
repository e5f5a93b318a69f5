// SPDX-License-Identifier: GPL-3.0-or-later
// simulate with --model planar (docs/user-guide.md "The command line"): the JSON of the
// 1-DOF model with keys added, never renamed: exit_side ("across" | "along", null unless
// collapsed), tau_lift_off, max_abs_delta_y, residual_delta_y, and the planar case.

#include "app/cli/Commands.h"
#include "app/cli/PlanarFlags.h"
#include "core/io/JsonText.h"
#include "core/io/PlanarResultJson.h"
#include "core/sweep/SearchWork.h"

#include <chrono>
#include <iostream>
#include <sstream>

namespace kinstab::cli {

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

    nlohmann::json j = planarResultJson(r, c.tauRef());
    j.update(planarCaseJson(c));
    j["amplitude"] = amplitude;
    j["frequency"] = frequency;
    j["tau_ref"] = c.tauRef();
    j["wall_time_s"] = wall;
    if (args.has("events")) j["events"] = planarEventsJson(log.events.events);
    if (args.has("history")) writeOutput(args, "history", planarHistoryCsv(model, log.path.path));
    std::cout << jsonText(j, 2) << "\n";
    return 0;
}

} // namespace kinstab::cli
