// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/AnalysisRuns.h"
#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "app/cli/ModelFlags.h"
#include "core/io/JsonText.h"
#include "core/io/ResultJson.h"
#include "core/io/ResultTable.h"
#include "core/io/SurfaceJson.h"

namespace kinstab::cli {

int runSurface(const ArgList& argv) {
    std::set<std::string> flags = modelFlagNames();
    flags.insert({"amplitudes", "frequencies", "threads", "format", "o"});
    const Args args(argv, flags);
    SweepGrid grid{args.list("amplitudes"), args.list("frequencies")};
    const std::string e = validateGrid(grid);
    if (!e.empty()) throw UsageError("--" + e);
    const int threads = args.integer("threads", 0);
    if (threads < 0 || threads > 1024)
        throw UsageError("--threads " + args.text("threads") + ": must be 0 (all) to 1024");
    const std::string format = args.choice("format", {"json", "csv", "table"}, "json");
    if (args.has("o")) checkOutputPath("o", args.text("o")); // before a long sweep, not after

    // One path for both models: the planar case shares the 1-DOF case's τ_ref.
    const AnalysisRequest request = modelRequestFromFlags(args);
    const SweepResult r = surfaceOf(request, grid, threads);
    const double tauRef = request.slab.tauRef();
    const std::optional<PlanarCase> planar = request.planarCase();
    if (format == "table") {
        writeOutput(args, "o", sweepTable(r, tauRef));
        return 0;
    }
    if (format == "csv") {
        writeOutput(args, "o", sweepCsv(r, tauRef));
        return 0;
    }
    const nlohmann::json j = planar ? surfaceJson(r, *planar) : surfaceJson(r, request.slab);
    writeOutput(args, "o", jsonText(j) + "\n");
    return 0;
}

} // namespace kinstab::cli
