// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli floors: the building's own floor motions under a ground record (shear-building
// model, all modes), the codes' floor-acceleration demands per level, the critical PGA at which
// the slab on each level falls and the verdicts at the slab's level
// (core/building/FloorAnalysis.h).

#include "app/cli/Args.h"
#include "app/cli/BuildingFlags.h"
#include "app/cli/Commands.h"
#include "app/cli/RecordFlags.h"
#include "core/assessment/AssessmentJson.h"
#include "core/assessment/RunAssessment.h"
#include "core/building/FloorAnalysis.h"
#include "core/io/AtomicFile.h"
#include "core/io/FloorsJson.h"
#include "core/io/JsonText.h"
#include "core/io/Project.h"

#include <chrono>

namespace kinstab::cli {

namespace {

Accelerogram groundFrom(const Args& args, const Project& p) {
    if (args.has("record")) return readRecordFromFlag(args, "record");
    if (!p.record)
        throw UsageError("--record: missing, and the project (--project " + args.text("project") +
                         ") has no excitation.record");
    try {
        return readGroundRecord(*p.record); // its floor filter is the model's business here
    } catch (const RecordError& e) {
        throw UsageError("excitation.record.file = '" + p.record->file + "': " + e.what());
    }
}

FloorSettings settingsFrom(const Args& args, const Project& p) {
    FloorSettings s = p.floors.value_or(FloorSettings{});
    if (args.has("stiffness"))
        s.stiffness = *stiffnessFromName(args.choice("stiffness", {"uniform", "weight"}, ""));
    s.damping = args.optionalInput(kModalDampingInput).value_or(s.damping);
    if (args.has("slab-level")) s.slabLevel = args.integer("slab-level", 0);
    args.refuse(checkFloorSettings(s, p.building.stories)); // core's rules, named by the flag
    return s;
}

} // namespace

int runFloors(const ArgList& argv) {
    std::set<std::string> flags = recordReadFlagNames();
    flags.insert({"project", "record", "stiffness", "damping", "slab-level", "history-csv"});
    const Args args(argv, flags, {"no-critical"});
    if (!args.has("project")) throw UsageError("missing required flag --project");
    const Project p = projectFromFlag(args);
    FloorAnalysisInput in = floorAnalysisInput(p, groundFrom(args, p));
    in.settings = settingsFrom(args, p);
    in.critical = !args.has("no-critical");
    const auto start = std::chrono::steady_clock::now();
    FloorAnalysis a;
    try {
        a = analyseFloors(in);
    } catch (const InputError& e) {
        throw inputUsageError(e);
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    nlohmann::json j = floorAnalysisJson(a, p.building);
    // The floor checks at the slab's level, as the project's assessment states them (check).
    Project asRun = p;
    asRun.floors = in.settings;
    AssessmentParts parts;
    parts.floors = floorCheckParts(a, p.building.stories);
    parts.recordName = in.ground.name;
    j["checks"] = assessmentJson(composeAssessment(asRun, parts))["checks"];
    j["project"] = p.name;
    j["record"] = accelerogramJson(in.ground);
    j["stiffness"] = stiffnessName(in.settings.stiffness);
    j["damping"] = in.settings.damping;
    j["wall_time_s"] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (args.has("history-csv")) writeOutput(args, "history-csv", floorHistoryCsv(a, in.ground));
    writeStandardOutput(jsonText(j, 2) + "\n");
    return 0;
}

} // namespace kinstab::cli
