// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/Args.h"
#include "app/cli/BuildingFlags.h"
#include "app/cli/Commands.h"
#include "app/cli/ModelFlags.h"
#include "app/cli/PlanarFlags.h"
#include "app/cli/RecordFlags.h"
#include "core/assessment/AssessmentJson.h"
#include "core/assessment/AssessmentRunJson.h"
#include "core/assessment/RunAssessment.h"
#include "core/io/AtomicFile.h"
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
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    writeStandardOutput(jsonText(assessmentRunJson(p, run, wall), 2) + "\n");
    return 0;
}

} // namespace kinstab::cli
