// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/Args.h"
#include "app/cli/BuildingFlags.h"
#include "app/cli/Commands.h"
#include "app/cli/ModelFlags.h"
#include "app/cli/RecordFlags.h"
#include "core/check/DesignCheck.h"
#include "core/check/RecordAnalysis.h"
#include "core/io/CodesJson.h"
#include "core/io/JsonText.h"
#include "core/io/Project.h"

#include <chrono>
#include <iostream>

namespace kinstab::cli {

namespace {
// A project whose excitation is a record: each code against the record's critical peak.
nlohmann::json recordCheckJson(const Project& p, const std::vector<CodeResult>& codes) {
    RecordAnalysisInput in;
    in.slab = p.slab;
    in.record = *p.record;
    in.search = p.critical;
    in.codes = codes;
    RecordAnalysis a;
    try {
        a = analyseRecord(in);
    } catch (const RecordError& e) {
        throw UsageError("excitation.record.file = '" + p.record->file + "': " + e.what());
    } catch (const std::invalid_argument& e) {
        throw UsageError(e.what());
    }
    nlohmann::json j = designCheckJson(DesignCheckResult{a.verdicts, a.critical->runs});
    j["record"] = accelerogramJson(a.ground);
    j["floor_filter"] = p.record->floor ? floorFilterJson(*p.record->floor) : nlohmann::json();
    j["amplitude"] = a.peak;
    j["critical_peak_g"] = a.critical->peak ? nlohmann::json(*a.critical->peak) : nlohmann::json();
    j["outcome"] = outcomeName(a.run.outcome);
    return j;
}
} // namespace

// The design check of chapter V for a project: per code the top-floor ratio, A_crit(1/T) (or
// the critical peak of the project's record), the margin and the verdict.
int runCheck(const ArgList& argv) {
    const Args args(argv, {"project"});
    if (!args.has("project")) throw UsageError("missing required flag --project");
    const Project p = projectFromFlag(args);
    if (p.codes.empty())
        throw UsageError("--project " + args.text("project") + ": the project selects no code");
    if (modelKindFromName(p.model) != ModelKind::Slab1D)
        throw UsageError("--project " + args.text("project") + ": model '" + p.model +
                         "': the design check uses the " + modelKindName(ModelKind::Slab1D) +
                         " model");
    const auto start = std::chrono::steady_clock::now();
    nlohmann::json j;
    try {
        const std::vector<CodeResult> codes = kinstab::runCodes(p.building, p.codes);
        j = p.record ? recordCheckJson(p, codes)
                     : designCheckJson(designCheck(codes, p.slab, p.critical));
    } catch (const InputError& e) {
        throw inputUsageError(e);
    }
    j["project"] = p.name;
    j["model"] = modelKindName(ModelKind::Slab1D);
    j["solver"] = solverName(p.slab.solver);
    if (!p.record) j["envelope"] = envelopeJson(p.slab);
    j["mu"] = p.slab.slab.mu;
    j["tstar"] = p.slab.tstar;
    j["search"] = {{"max_amplitude", p.critical.to},
                   {"scan_step", p.critical.scanStep},
                   {"tolerance", p.critical.tolerance}};
    j["wall_time_s"] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << jsonText(j, 2) << "\n";
    return 0;
}

} // namespace kinstab::cli
