// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/Args.h"
#include "app/cli/BuildingFlags.h"
#include "app/cli/Commands.h"
#include "app/cli/ModelFlags.h"
#include "app/cli/PlanarFlags.h"
#include "app/cli/RecordFlags.h"
#include "core/analysis/RunAnalysis.h"
#include "core/io/CaseJson.h"
#include "core/io/CodesJson.h"
#include "core/io/JsonText.h"
#include "core/io/Project.h"
#include "report/PlanarVertical.h"

#include <chrono>
#include <iostream>

namespace kinstab::cli {

namespace {
AnalysisRequest checkRequest(const Project& p, const std::vector<CodeResult>& codes) {
    AnalysisRequest request;
    request.slab = p.slab;
    request.codes = codes;
    request.checkSearch = p.critical;
    return request;
}

// The model the sine's check runs: the 1-DOF slab (none), or the planar slab of Furgerson 1980
// ch. VI with the project's planar settings and its vertical record read. Throws InputError.
std::optional<PlanarCase> planarModel(const Project& p) {
    if (p.model != ModelKind::Planar) return std::nullopt;
    return ui::projectPlanarCase(p.slab, p.planar);
}

// A project whose excitation is the enveloped sine: each code against A_crit(1/T) of its model.
nlohmann::json sineCheckJson(const Project& p, const std::vector<CodeResult>& codes,
                             const std::optional<PlanarCase>& planar) {
    AnalysisRequest request = checkRequest(p, codes);
    request.planar = planar;
    request.parts.designCheck = true;
    AnalysisControl control;
    const AnalysisResult r = runAnalysis(request, control);
    if (r.checkError) std::rethrow_exception(r.checkError);
    return designCheckJson(*r.check);
}

// A project whose excitation is a record: each code against the record's critical peak.
nlohmann::json recordCheckJson(const Project& p, const std::vector<CodeResult>& codes) {
    AnalysisRequest request = checkRequest(p, codes);
    request.record = p.record;
    request.parts.recordCheck = true;
    RecordAnalysis a;
    try {
        AnalysisControl control;
        a = *runAnalysis(request, control).record;
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

// The design check of chapter V for a project: per code the top-floor ratio, A_crit(1/T) of the
// project's model (or the critical peak of the project's record), the margin and the verdict.
int runCheck(const ArgList& argv) {
    const Args args(argv, {"project"});
    if (!args.has("project")) throw UsageError("missing required flag --project");
    const Project p = projectFromFlag(args);
    if (p.codes.empty())
        throw UsageError("--project " + args.text("project") + ": the project selects no code");
    if (p.model != ModelKind::Slab1D && p.record)
        throw UsageError("--project " + args.text("project") + ": model '" +
                         modelKindName(p.model) + "': the check against a record uses the " +
                         modelKindName(ModelKind::Slab1D) + " model");
    const auto start = std::chrono::steady_clock::now();
    nlohmann::json j;
    std::optional<PlanarCase> planar;
    try {
        const std::vector<CodeResult> codes = kinstab::runCodes(p.building, p.codes);
        planar = planarModel(p);
        j = p.record ? recordCheckJson(p, codes) : sineCheckJson(p, codes, planar);
    } catch (const InputError& e) {
        throw inputUsageError(e);
    }
    j["project"] = p.name;
    if (planar) {
        j.update(planarCaseJson(*planar)); // model, solver, envelope, mu, t*, the planar inputs
    } else {
        j["model"] = modelKindName(ModelKind::Slab1D);
        j["solver"] = solverName(p.slab.solver);
        if (!p.record) j["envelope"] = envelopeJson(p.slab);
        j["mu"] = p.slab.slab.mu;
        j["tstar"] = p.slab.tstar;
    }
    j["search"] = {{"max_amplitude", p.critical.to},
                   {"scan_step", p.critical.scanStep},
                   {"tolerance", p.critical.tolerance}};
    j["wall_time_s"] =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << jsonText(j, 2) << "\n";
    return 0;
}

} // namespace kinstab::cli
