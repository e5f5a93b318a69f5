// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli precision: the work-precision study (docs/theory.md §6.6), printed as a table, CSV
// with -o.

#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "core/precision/PlanarPrecision.h"
#include "core/precision/WorkPrecision.h"
#include "core/slab/VerticalRecord.h"

#include <iostream>

namespace kinstab::cli {

int runPrecision(const ArgList& argv) {
    const Args args(argv, {"o", "repeats"}, {"no-regularized"});
    WorkPrecisionOptions options;
    options.repeats = args.integer("repeats", 5);
    if (options.repeats < 1 || options.repeats > 1000)
        throw UsageError("--repeats " + args.text("repeats") + ": must be 1 to 1000");
    options.includeRegularized = !args.has("no-regularized");
    options.onProgress = [](std::size_t done, std::size_t total) {
        std::cerr << "\rprecision: " << done << "/" << total << " settings" << std::flush;
        if (done == total) std::cerr << "\n";
    };
    const WorkPrecisionStudy study = runWorkPrecisionStudy(options);
    std::cout << workPrecisionText(study);
    // The planar model: its rows follow the 1-DOF ones in the table and the CSV.
    PlanarPrecisionOptions planar;
    planar.repeats = options.repeats;
    planar.verticalUp = planarCaseWithVertical({}, PlanarSettings{}).vertical; // shipped RSN68 UP
    planar.onProgress = options.onProgress;
    const PlanarPrecisionStudy planarStudy = runPlanarPrecisionStudy(planar);
    std::cout << planarPrecisionText(planarStudy);
    WorkPrecisionStudy all = study;
    all.rows.insert(all.rows.end(), planarStudy.rows.begin(), planarStudy.rows.end());
    if (args.has("o")) writeOutput(args, "o", workPrecisionCsv(all));
    return 0;
}

} // namespace kinstab::cli
