// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli bench: the surface speed target (exact against paper at T/16, one process);
// with --model planar, the planar surface against the 1-DOF one on the same grid; with --record
// FILE, the record path (a record run against a sine run, the envelope fit's share, the record's
// critical search against the sine's).

#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "app/cli/ModelFlags.h"
#include "app/cli/PlanarFlags.h"
#include "app/cli/RecordFlags.h"
#include "app/cli/SearchFlags.h"
#include "core/check/RecordBenchmark.h"
#include "core/io/BenchJson.h"
#include "core/io/JsonText.h"
#include "core/io/StudySpecJson.h"
#include "core/records/RecordReader.h"
#include "core/rocking/RockingBenchmark.h"
#include "core/study/CpuAffinity.h"
#include "core/study/StudyBenchmark.h"
#include "core/study/StudyRecords.h"
#include "core/sweep/SurfaceBenchmark.h"

#include <cstdio>
#include <iostream>
#include <string>

namespace kinstab::cli {

namespace {
// The human summary on stderr: the grid, then one line per timed variant (label padded by the
// caller, `digits` decimals of seconds).
void printHeader(const SweepGrid& grid, const char* what, int threads, int runs) {
    std::fprintf(stderr, "%zux%zu %s, %d threads, %d alternating runs of each after a warm-up:\n",
                 grid.amplitudes.size(), grid.frequencies.size(), what, threads, runs);
}
void printTiming(const std::string& label, const TimingStats& t, int digits) {
    std::fprintf(stderr, "  %s median %.*f s (min %.*f s, CPU %.*f s)\n", label.c_str(), digits,
                 t.medianSeconds, digits, t.minSeconds, digits, t.medianCpuSeconds);
}

// Planar against 1-DOF (exact) on one grid, alternating in one process (issue 22).
int runBenchPlanar(const Args& args, const SweepGrid& grid, int threads, int repeats) {
    const PlanarCase planar = planarCaseFromFlags(args);
    const Slab1DCase oneDof = commonCaseFromFlags(args);
    const PlanarSurfaceBenchmark b = benchmarkPlanarSurface(oneDof, planar, grid, repeats, threads);
    std::cout << jsonText(planarBenchmarkJson(b, planar, grid), 2) << "\n";
    printHeader(grid, "surface", b.threads, b.planar.runs);
    printTiming(std::string("planar (") + (planar.vertical ? "with" : "no") + " vertical) ",
                b.planar, 4);
    printTiming("1-DOF exact          ", b.oneDof, 4);
    std::fprintf(stderr, "  planar/1-DOF %.2f (wall), %.2f (CPU), medians of per-run ratios\n",
                 b.ratioMedian, b.ratioCpu);
    return 0;
}
// The exact surface with and without core/numerics/VectorState.h's clearing, alternating in one
// process (issue 15: is the workaround still needed now that the CLI loads no Qml?).
int runBenchVectorState(const Slab1DCase& c, const SweepGrid& grid, int threads, int repeats) {
    const VectorStateBenchmark b = benchmarkVectorState(c, grid, repeats, threads);
    std::cout << jsonText(vectorStateBenchmarkJson(b, grid), 2) << "\n";
    printHeader(grid, "exact surface", b.threads, b.cleared.runs);
    printTiming("with vzeroupper    ", b.cleared, 3);
    printTiming("without vzeroupper ", b.uncleared, 3);
    std::fprintf(stderr, "  without/with %.3f (wall), %.3f (CPU), medians of per-run ratios\n",
                 b.ratioMedian, b.ratioCpu);
    return 0;
}
// The record path (issue 34): a record run against a sine run, the fit's share of the record run,
// and the record's critical search against the sine's, each pair alternating in this process.
int runBenchRecord(const Args& args, int repeats) {
    const Slab1DCase c = slab1DCaseFromFlags(args, true);
    const RecordExcitation record = recordExcitationFromFlags(args, "record");
    const CriticalSearch search = criticalSearchFromFlags(args);
    constexpr double amplitude = 1.0, frequency = 1.0; // g, Hz: the sine's point
    RecordBenchmark b;
    try {
        b = benchmarkRecord(c, record, search, amplitude, frequency, repeats);
    } catch (const RecordError& e) {
        throw UsageError("--record " + args.text("record") + ": " + e.what());
    } catch (const std::invalid_argument& e) {
        throw UsageError("--record " + args.text("record") + ": " + e.what());
    }
    std::cout << jsonText(recordBenchmarkJson(b, c, record.file, amplitude, frequency), 2) << "\n";
    std::fprintf(stderr, "record %s, mu %g, %d alternating runs of each pair after a warm-up:\n",
                 record.file.c_str(), c.slab.mu, b.recordRun.runs);
    printTiming("record run (read, filter, fit, solve)", b.recordRun, 5);
    printTiming("sine run                             ", b.sineRun, 6);
    std::fprintf(stderr, "  record/sine %.1f (wall), %.1f (CPU)\n", b.recordOverSine,
                 b.recordOverSineCpu);
    printTiming("envelope fit                         ", b.fit, 5);
    std::fprintf(stderr, "  fit/record run %.3f (wall), %.3f (CPU)\n", b.fitShare, b.fitShareCpu);
    printTiming("record critical search               ", b.recordCritical, 4);
    printTiming("sine critical search                 ", b.sineCritical, 4);
    std::fprintf(stderr, "  record/sine search %.2f (wall), %.2f (CPU); %ld and %ld runs\n",
                 b.criticalRatio, b.criticalRatioCpu, b.recordCriticalRuns, b.sineCriticalRuns);
    return 0;
}
// The free-standing block (issue 32): one pulse run, and the 257 x 257 overturning map
// (target: under 2 s on two cores).
int runBenchRocking(const Args& args, int threads, int repeats) {
    const int points = args.integer("map-points", 257);
    if (points < 2 || points > 4097)
        throw UsageError("--map-points " + args.text("map-points") + ": must be 2 to 4097");
    const RockingBenchmark b = benchmarkRocking(points, repeats, threads);
    std::cout << jsonText(rockingBenchmarkJson(b), 2) << "\n";
    std::fprintf(stderr, "free-standing block, %d timed runs of each after a warm-up:\n",
                 b.mapLinear.runs);
    std::fprintf(stderr, "  one pulse run      median %.1f us (min %.1f us)\n",
                 b.pulseRun.medianSeconds * 1e6, b.pulseRun.minSeconds * 1e6);
    std::fprintf(stderr, "%dx%d overturning map, one-sine, %d threads:\n", points, points,
                 b.threads);
    printTiming("linearised ", b.mapLinear, 3);
    printTiming("exact      ", b.mapExact, 3);
    return 0;
}

// A study's throughput (issue 34): all its cases on one thread and on --threads threads,
// alternating in this process; cases per CPU-second and the threads' speed-up.
int runBenchStudy(const Args& args, int threads, int repeats) {
    const std::string path = args.text("study");
    StudySpec spec;
    try {
        spec = loadStudy(path);
        loadStudyRecords(spec); // each record read once, as `study` does
    } catch (const StudyError& e) {
        throw UsageError("--study " + path + ": " + e.what());
    }
    const int n = threads > 0 ? threads : static_cast<int>(allowedCpuCount());
    const StudyBenchmark b = benchmarkStudy(spec, n, repeats);
    std::cout << jsonText(studyBenchmarkJson(b, path), 2) << "\n";
    std::fprintf(stderr, "study %s, %zu cases, 1 and %d threads, %d alternating runs each:\n",
                 path.c_str(), b.cases, b.threads, b.one.runs);
    printTiming("1 thread  ", b.one, 4);
    printTiming(std::to_string(b.threads) + " threads ", b.many, 4);
    std::fprintf(stderr, "  %.0f and %.0f cases per CPU-second; speed-up %.2f (wall); rows %s\n",
                 b.perCpuSecondOne, b.perCpuSecondMany, b.speedup,
                 b.rowsAgree ? "identical" : "DIFFER");
    return b.rowsAgree ? 0 : 1;
}
// The exact surface against the paper's RK4 at T/16 on one grid (the default bench).
int runBenchSurface(const Slab1DCase& c, const SweepGrid& grid, int threads, int repeats) {
    const SurfaceBenchmark b = benchmarkSurface(c, grid, repeats, threads);
    const nlohmann::json j = surfaceBenchmarkJson(b, c, grid);
    std::cout << jsonText(j, 2) << "\n";
    printHeader(grid, "surface", b.threads, b.exact.runs);
    printTiming("exact      ", b.exact, 3);
    char paper[32];
    std::snprintf(paper, sizeof paper, "paper T/%g ", c.paperStepsPerPeriod);
    printTiming(paper, b.paper, 3);
    std::fprintf(stderr,
                 "  exact/paper %.2f (wall), %.2f (CPU), medians of per-run ratios; outcomes "
                 "differ at %zu points\n",
                 b.ratioMedian, b.ratioCpu, b.outcomeDisagreements);
    std::fprintf(stderr,
                 "  exact: %.2f us CPU per point, %.1f events per point, %.2f evaluations per "
                 "event\n",
                 j["exact_cpu_us_per_point"].get<double>(),
                 j["exact_events_per_point"].get<double>(),
                 j["exact_evaluations_per_event"].get<double>());
    return 0;
}

Args benchArgs(const ArgList& argv) {
    std::set<std::string> flags = modelFlagNames();
    flags.insert(
        {"amplitudes", "frequencies", "threads", "repeats", "amplitude", "scale-factor", "study"});
    flags.merge(recordReadFlagNames());
    flags.merge(searchFlagNames());
    flags.insert("map-points");
    return Args(argv, flags, {"vector-state", "rocking"});
}

// The model's benchmark grid, or the one --amplitudes/--frequencies give.
SweepGrid benchGrid(const Args& args, bool planar) {
    SweepGrid grid = planar ? planarBenchmarkGrid() : benchmarkGrid();
    if (args.has("amplitudes")) grid.amplitudes = args.list("amplitudes");
    if (args.has("frequencies")) grid.frequencies = args.list("frequencies");
    const std::string e = validateGrid(grid);
    if (!e.empty()) throw UsageError("--" + e);
    return grid;
}

// The flags only --record uses, refused on the surface benches.
void refuseRecordOnlyFlags(const Args& args) {
    for (const std::string f : {"amplitude", "scale-factor"})
        if (args.has(f)) throw UsageError("--" + f + " " + args.text(f) + ": needs --record FILE");
    for (const std::string& f : searchFlagNames())
        if (args.has(f)) throw UsageError("--" + f + " " + args.text(f) + ": needs --record FILE");
}
} // namespace

int runBench(const ArgList& argv) {
    const Args args = benchArgs(argv);
    if (args.has("solver"))
        throw UsageError("--solver: bench always runs both solvers (exact and paper)");
    const bool planar = isPlanar(args);
    const SweepGrid grid = benchGrid(args, planar);
    const int threads = args.integer("threads", 0);
    if (threads < 0 || threads > 1024)
        throw UsageError("--threads " + args.text("threads") + ": must be 0 (all) to 1024");
    const int repeats = args.integer("repeats", 5);
    if (repeats < 1 || repeats > 1000)
        throw UsageError("--repeats " + args.text("repeats") + ": must be 1 to 1000");
    if (args.has("rocking")) return runBenchRocking(args, threads, repeats);
    if (args.has("map-points")) throw UsageError("--map-points: needs --rocking");
    if (args.has("study")) {
        if (planar || args.has("vector-state") || args.has("record"))
            throw UsageError("--study: times the study alone");
        return runBenchStudy(args, threads, repeats);
    }
    if (args.has("record")) {
        if (planar || args.has("vector-state"))
            throw UsageError("--record: times the 1-DOF record path alone");
        return runBenchRecord(args, repeats);
    }
    refuseRecordOnlyFlags(args);
    if (planar && args.has("vector-state"))
        throw UsageError("--vector-state: times the 1-DOF exact solver, not --model planar");
    if (planar) return runBenchPlanar(args, grid, threads, repeats);
    const Slab1DCase c = slab1DCaseFromFlags(args);
    if (args.has("vector-state")) return runBenchVectorState(c, grid, threads, repeats);
    return runBenchSurface(c, grid, threads, repeats);
}

} // namespace kinstab::cli
