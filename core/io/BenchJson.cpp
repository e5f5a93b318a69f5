// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/BenchJson.h"

#include "core/io/CaseJson.h"

namespace kinstab {

using nlohmann::json;

namespace {

// The grid and thread count every surface bench reports first.
json gridJson(const SweepGrid& grid, int threads) {
    return {{"amplitudes", grid.amplitudes.size()},
            {"frequencies", grid.frequencies.size()},
            {"points", grid.size()},
            {"threads", threads}};
}

} // namespace

json timingJson(const TimingStats& t) {
    return {{"min_s", t.minSeconds},
            {"median_s", t.medianSeconds},
            {"median_cpu_s", t.medianCpuSeconds},
            {"runs", t.runs}};
}

json surfaceBenchmarkJson(const SurfaceBenchmark& b, const Slab1DCase& c, const SweepGrid& grid) {
    const double points = static_cast<double>(grid.size());
    const double perEvent =
        b.exactEvents > 0 ? static_cast<double>(b.exactEvaluations) / b.exactEvents : 0.0;
    json j = gridJson(grid, b.threads);
    j.update({{"envelope", envelopeJson(c)},
              {"mu", c.slab.mu},
              {"paper_steps_per_period", c.paperStepsPerPeriod},
              {"exact", timingJson(b.exact)},
              {"paper", timingJson(b.paper)},
              {"ratio_exact_over_paper", b.ratioMedian},
              {"ratio_exact_over_paper_cpu", b.ratioCpu},
              {"exact_collapsed_points", b.exactCollapsed},
              {"outcome_disagreements", b.outcomeDisagreements},
              {"exact_cpu_us_per_point", 1e6 * b.exact.medianCpuSeconds / points},
              {"exact_events_per_point", static_cast<double>(b.exactEvents) / points},
              {"exact_evaluations_per_event", perEvent}});
    return j;
}

json planarBenchmarkJson(const PlanarSurfaceBenchmark& b, const PlanarCase& c,
                         const SweepGrid& grid) {
    json j = planarCaseJson(c);
    j.update(gridJson(grid, b.threads));
    j.update({{"planar", timingJson(b.planar)},
              {"one_dof", timingJson(b.oneDof)},
              {"ratio_planar_over_one_dof", b.ratioMedian},
              {"ratio_planar_over_one_dof_cpu", b.ratioCpu},
              {"planar_collapsed_points", b.planarCollapsed},
              {"planar_along_wall_points", b.planarAlongWalls},
              {"planar_lift_off_points", b.planarLiftOff},
              {"planar_steps", b.planarSteps},
              {"planar_accel_evaluations", b.planarEvaluations}});
    return j;
}

json vectorStateBenchmarkJson(const VectorStateBenchmark& b, const SweepGrid& grid) {
    json j = gridJson(grid, b.threads);
    j.update({{"with_vzeroupper", timingJson(b.cleared)},
              {"without_vzeroupper", timingJson(b.uncleared)},
              {"ratio_without_over_with", b.ratioMedian},
              {"ratio_without_over_with_cpu", b.ratioCpu}});
    return j;
}

json recordBenchmarkJson(const RecordBenchmark& b, const Slab1DCase& c, const std::string& record,
                         double amplitude, double frequency) {
    return {{"record", record},
            {"mu", c.slab.mu},
            {"tstar", c.tstar},
            {"sine_amplitude", amplitude},
            {"sine_frequency", frequency},
            {"record_run", timingJson(b.recordRun)},
            {"sine_run", timingJson(b.sineRun)},
            {"ratio_record_over_sine", b.recordOverSine},
            {"ratio_record_over_sine_cpu", b.recordOverSineCpu},
            {"envelope_fit", timingJson(b.fit)},
            {"fit_share_of_record_run", b.fitShare},
            {"fit_share_of_record_run_cpu", b.fitShareCpu},
            {"record_critical", timingJson(b.recordCritical)},
            {"sine_critical", timingJson(b.sineCritical)},
            {"ratio_record_critical_over_sine_critical", b.criticalRatio},
            {"ratio_record_critical_over_sine_critical_cpu", b.criticalRatioCpu},
            {"record_critical_runs", b.recordCriticalRuns},
            {"sine_critical_runs", b.sineCriticalRuns}};
}

json rockingBenchmarkJson(const RockingBenchmark& b) {
    return {{"pulse_run", timingJson(b.pulseRun)},
            {"pulse_runs_per_timing", b.runsPerTiming},
            {"map_points", b.mapPoints},
            {"map_threads", b.threads},
            {"map_linear", timingJson(b.mapLinear)},
            {"map_exact", timingJson(b.mapExact)},
            {"map_linear_overturning_points", b.overturnsLinear},
            {"map_exact_overturning_points", b.overturnsExact}};
}

json studyBenchmarkJson(const StudyBenchmark& b, const std::string& study) {
    return {{"study", study},
            {"cases", b.cases},
            {"threads", b.threads},
            {"one_thread", timingJson(b.one)},
            {"threads_run", timingJson(b.many)},
            {"cases_per_cpu_second_one_thread", b.perCpuSecondOne},
            {"cases_per_cpu_second_threads", b.perCpuSecondMany},
            {"speedup_threads_over_one", b.speedup},
            {"rows_identical", b.rowsAgree}};
}

} // namespace kinstab
