// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/AnalysisRuns.h"
#include "app/cli/Args.h"
#include "app/cli/BuildingFlags.h"
#include "app/cli/Commands.h"
#include "app/cli/ModelFlags.h"
#include "app/cli/PlanarFlags.h"
#include "app/cli/RecordFlags.h"
#include "core/assessment/AssessmentJson.h"
#include "core/assessment/RunAssessment.h"
#include "core/io/AtomicFile.h"
#include "core/io/CaseJson.h"
#include "core/io/CodesJson.h"
#include "core/io/JsonText.h"
#include "core/io/Project.h"
#include "core/slab/VerticalRecord.h"

#include <unistd.h>

#include <chrono>

namespace kinstab::cli {

namespace {

// The model the sine's checks run: the 1-DOF slab (none), or the planar slab of Furgerson 1980
// ch. VI with the project's planar settings and its vertical record read. Throws InputError.
std::optional<PlanarCase> planarModel(const Project& p) {
    if (p.model != ModelKind::Planar) return std::nullopt;
    return planarCaseWithVertical(p.slab, p.planar);
}

AssessmentRun assess(const Project& p, const std::optional<PlanarCase>& planar) {
    AnalysisControl control;
    try {
        return runAssessment(p, planar, control);
    } catch (const RecordError& e) {
        throw UsageError("excitation.record.file = '" + p.record->file + "': " + e.what());
    } catch (const InputError&) {
        throw;
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
}

// The per-basis figures kept from before the assessment (keys are never renamed): "codes" holds
// the record's verdicts for a record project, the sine's otherwise.
nlohmann::json detailJson(const Project& p, const AssessmentRun& run) {
    if (!run.record) return designCheckJson(*run.parts.sine);
    const RecordAnalysis& a = *run.record;
    nlohmann::json j = designCheckJson(DesignCheckResult{a.verdicts, a.critical->runs});
    j["record"] = accelerogramJson(a.ground);
    j["floor_filter"] = p.record->floor ? floorFilterJson(*p.record->floor) : nlohmann::json();
    j["amplitude"] = a.peak;
    j["critical_peak_g"] = a.critical->peak ? nlohmann::json(*a.critical->peak) : nlohmann::json();
    j["outcome"] = outcomeName(a.run.outcome);
    return j;
}

} // namespace

// The project's assessment (core/assessment): every check the project implies (the sine's or
// planar model's A_crit(1/T), the record's critical peak, the floors' critical ground PGA), each
// with its margin and verdict, and the governing one. JSON when piped (the assessment under
// "assessment"), a table on a terminal; --format chooses.
int runCheck(const ArgList& argv) {
    const Args args(argv, {"project", "format"});
    if (!args.has("project")) throw UsageError("missing required flag --project");
    const std::string format =
        args.choice("format", {"json", "table"}, isatty(STDOUT_FILENO) ? "table" : "json");
    const Project p = projectFromFlag(args);
    if (p.codes.empty())
        throw UsageError("--project " + args.text("project") + ": the project selects no code");
    if (p.model != ModelKind::Slab1D && p.record)
        throw UsageError("--project " + args.text("project") + ": model '" +
                         modelKindName(p.model) + "': the check against a record uses the " +
                         modelKindName(ModelKind::Slab1D) + " model");
    const auto start = std::chrono::steady_clock::now();
    nlohmann::json j;
    AssessmentRun run;
    try {
        run = assess(p, planarModel(p));
    } catch (const InputError& e) {
        throw inputUsageError(e);
    }
    if (format == "table") {
        writeStandardOutput(p.name + "\n\n" + assessmentTable(run.assessment));
        return 0;
    }
    j = detailJson(p, run);
    j["assessment"] = assessmentJson(run.assessment);
    j["project"] = p.name;
    // model, solver, envelope, mu, t* (and the planar inputs); a record replaces the envelope.
    j.update(modelKeysJson(run.request));
    if (p.record) j.erase("envelope");
    j["search"] = {{"max_amplitude", p.critical.to},
                   {"scan_step", p.critical.scanStep},
                   {"tolerance", p.critical.tolerance}};
    j["wall_time_s"] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    writeStandardOutput(jsonText(j, 2) + "\n");
    return 0;
}

} // namespace kinstab::cli
