// kinstab-cli bench: the surface speed target (exact against paper at T/16, one process).

#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "app/cli/JsonText.h"
#include "app/cli/ModelFlags.h"
#include "core/sweep/SurfaceBenchmark.h"

#include <cstdio>
#include <iostream>

namespace kinstab::cli {

namespace {
nlohmann::json timingJson(const TimingStats& t) {
    return {{"min_s", t.minSeconds},
            {"median_s", t.medianSeconds},
            {"median_cpu_s", t.medianCpuSeconds},
            {"runs", t.runs}};
}
} // namespace

int runBench(const ArgList& argv) {
    std::set<std::string> flags = modelFlagNames();
    flags.insert({"amplitudes", "frequencies", "threads", "repeats"});
    const Args args(argv, flags);
    if (args.has("solver"))
        throw UsageError("--solver: bench always runs both solvers (exact and paper)");
    const Slab1DCase c = slab1DCaseFromFlags(args);
    SweepGrid grid = benchmarkGrid();
    if (args.has("amplitudes")) grid.amplitudes = args.list("amplitudes");
    if (args.has("frequencies")) grid.frequencies = args.list("frequencies");
    const std::string e = validateGrid(grid);
    if (!e.empty()) throw UsageError("--" + e);
    const int threads = args.integer("threads", 0);
    if (threads < 0 || threads > 1024)
        throw UsageError("--threads " + args.text("threads") + ": must be 0 (all) to 1024");
    const int repeats = args.integer("repeats", 5);
    if (repeats < 1 || repeats > 1000)
        throw UsageError("--repeats " + args.text("repeats") + ": must be 1 to 1000");

    const SurfaceBenchmark b = benchmarkSurface(c, grid, repeats, threads);
    nlohmann::json j = {{"amplitudes", grid.amplitudes.size()},
                        {"frequencies", grid.frequencies.size()},
                        {"points", grid.size()},
                        {"threads", b.threads},
                        {"envelope", envelopeJson(c)},
                        {"mu", c.slab.mu},
                        {"paper_steps_per_period", c.paperStepsPerPeriod},
                        {"exact", timingJson(b.exact)},
                        {"paper", timingJson(b.paper)},
                        {"ratio_exact_over_paper", b.ratioMedian},
                        {"ratio_exact_over_paper_cpu", b.ratioCpu},
                        {"exact_collapsed_points", b.exactCollapsed},
                        {"outcome_disagreements", b.outcomeDisagreements}};
    std::cout << jsonText(j, 2) << "\n";
    std::fprintf(stderr,
                 "%zux%zu surface, %d threads, %d alternating runs of each after a warm-up:\n"
                 "  exact       median %.3f s (min %.3f s, CPU %.3f s)\n"
                 "  paper T/%g  median %.3f s (min %.3f s, CPU %.3f s)\n"
                 "  exact/paper %.2f (wall), %.2f (CPU), medians of per-run ratios; outcomes "
                 "differ at %zu points\n",
                 grid.amplitudes.size(), grid.frequencies.size(), b.threads, b.exact.runs,
                 b.exact.medianSeconds, b.exact.minSeconds, b.exact.medianCpuSeconds,
                 c.paperStepsPerPeriod, b.paper.medianSeconds, b.paper.minSeconds,
                 b.paper.medianCpuSeconds, b.ratioMedian, b.ratioCpu, b.outcomeDisagreements);
    return 0;
}

} // namespace kinstab::cli
