// SPDX-License-Identifier: GPL-3.0-or-later
// Over 400 lines with its header for a reason: every check is composed, named and worded here,
// so that the ids, the verdict words and the governing rule are read together; what each check
// needs is gathered apart (RunAssessment, BlockCheck, RiskCheck).
#include "core/assessment/Assessment.h"

#include "core/base/SignificantDigits.h"
#include "core/base/TextInput.h"
#include "core/codes/CodeCatalog.h"
#include "core/io/Project.h"

#include <cmath>
#include <filesystem>
#include <iomanip>
#include <locale>
#include <sstream>

namespace kinstab {

namespace {

std::string g(double x) {
    return significantDigits(x, 4);
}

std::string verticalText(const PlanarSettings& s) {
    switch (s.vertical) {
    case VerticalSource::None:
        return "no vertical motion (gravity only)";
    case VerticalSource::Rsn68Up:
        return "vertical motion RSN68 UP";
    case VerticalSource::File:
        return "vertical motion from " + s.verticalPath;
    }
    return {};
}

// The paper's words at the design level (ch. V: which limit the code's force reaches first);
// at MCE_R, and for the floor checks, whether the slab stays on its walls.
std::string verdictWords(CheckBasis basis, CheckLevel level, bool holds) {
    if (basis == CheckBasis::Risk)
        return holds ? "meets the target rate of collapse" : "exceeds the target rate of collapse";
    if (basis != CheckBasis::Floors)
        return verdictText(holds ? Verdict::OverstressGoverns : Verdict::KineticInstabilityGoverns);
    const std::string at = level == CheckLevel::MceR ? "at the MCE_R level" : "at the design level";
    return (holds ? "slab stays seated " : "slab slides off ") + at;
}

void finish(Check& c) {
    settleComparisons(c);
    c.verdict = verdictWords(c.basis, c.level, c.holds);
}

// A code's top-floor ratio against a critical top-floor peak (sine, planar or record).
Check codeRatioCheck(CheckBasis basis, const CodeVerdict& v, const std::string& model,
                     const std::string& excitation, const std::string& capacityName,
                     double searchLimit) {
    Check c;
    c.basis = basis;
    c.code = v.code;
    c.codeTitle = v.title;
    c.id = checkBasisName(basis) + "." + v.code;
    c.model = model;
    c.excitation = excitation;
    Comparison x;
    x.intensity = "floor peak acceleration";
    x.unit = "g";
    x.demandName = "F_top/w_top";
    x.demand = v.ratio;
    x.capacityName = capacityName;
    x.capacity = v.aCrit;
    x.searchLimit = searchLimit;
    x.margin = v.margin;
    c.comparisons.push_back(x);
    finish(c);
    return c;
}

std::string levelSuffix(const FloorDemand& d) {
    if (d.code == "asce7_22_mce") return "asce7_22.mce_r";
    if (d.code == "asce7_22") return "asce7_22.design";
    return d.code;
}

std::string floorModelText(const Project& p, const FloorCheckParts& f) {
    const FloorSettings s = p.floors.value_or(FloorSettings{});
    return slabModelText(p, ModelKind::Slab1D) + " on level " + std::to_string(f.atSlab.level) +
           " of " + std::to_string(f.stories) + " of the shear-building model (" +
           stiffnessName(s.stiffness) + " storey stiffness, " + g(100 * s.damping) +
           " % damping in every mode)";
}

Check floorCheck(const Project& p, const FloorCheckParts& f, const FloorDemand& d,
                 const std::string& recordName, double searchLimit) {
    Check c;
    c.basis = CheckBasis::Floors;
    c.code = d.code == "asce7_22_mce" ? "asce7_22" : d.code;
    c.codeTitle = d.title;
    c.level = d.code == "asce7_22_mce" ? CheckLevel::MceR : CheckLevel::Design;
    c.id = "floors." + levelSuffix(d);
    c.model = floorModelText(p, f);
    c.excitation = "ground record " + recordName + " scaled to the code level's ground motion";
    const std::string level = "level " + std::to_string(f.atSlab.level);
    // The building model: the ground motion the code level implies against the ground PGA at
    // which the slab falls. Both are ground intensities, so the margin falls whenever the slab
    // falls at a lower ground intensity, whatever the floor amplification.
    Comparison ground;
    ground.intensity = "ground PGA";
    ground.unit = "g";
    ground.demandName = d.groundPgaSource;
    ground.demand = d.groundPga;
    ground.capacityName = "critical ground PGA, slab on " + level;
    ground.capacity = f.atSlab.criticalPga;
    ground.searchLimit = f.atSlab.floorPeak > 0 ? searchLimit * f.pga / f.atSlab.floorPeak : 0;
    if (ground.capacity && ground.demand > 0) ground.margin = *ground.capacity / ground.demand;
    // The code's own floor formula: its peak floor acceleration at the slab's level against
    // the critical floor peak there.
    Comparison formula;
    formula.intensity = "floor peak acceleration, " + level;
    formula.unit = "g";
    formula.demandName = "PFA of " + d.title;
    formula.demand = d.slabPfa;
    formula.capacityName = "critical floor peak, " + level;
    formula.capacity = f.atSlab.criticalFloorPeak;
    formula.searchLimit = searchLimit;
    if (formula.capacity && formula.demand > 0) formula.margin = *formula.capacity / formula.demand;
    c.comparisons = {ground, formula};
    finish(c);
    return c;
}

// Rates to 3 significant digits as every table prints them ("2.01e-04"): fixed notation would
// spend most digits on zeros.
std::string rateText(double x) {
    std::ostringstream s;
    s.imbue(std::locale::classic());
    s << std::scientific << std::setprecision(2) << x;
    return s.str();
}

std::string riskModelText(const RiskCheckParts& r, const RiskSetPart& set) {
    std::string s = "collapse fragility of study set " + std::to_string(set.parameters.set) +
                    " (mu = " + g(set.parameters.mu) + ", t* = " + g(set.parameters.tstar) +
                    " s, " + studyDriverText(set.parameters) + "; " +
                    std::to_string(set.collapsed) + " of " + std::to_string(set.records) +
                    " records collapsed)";
    if (set.risk)
        s += ": lognormal, median " + g(set.risk->fragility.medianG) + " g " + r.measure +
             ", beta = " + g(set.risk->fragility.beta);
    return s;
}

// The file by its name (the report prints it on page 1, where a full path says nothing of the
// site), with what the reader picked in it (OpenQuake's site row, USGS's response).
std::string riskExcitationText(const RiskCheckParts& r) {
    const std::string& file = r.hazard.file;
    const std::string& source = r.curve.source;
    const std::string picked =
        source.compare(0, file.size(), file) == 0 ? source.substr(file.size()) : "";
    return "hazard curve " + std::filesystem::path(file).filename().string() + picked + " (" +
           hazardMeasureName(r.curve.measure) + ", " + r.curve.format + ")";
}

// lambda_C against the target rate: the demand is the rate at which the slab falls, the
// capacity the rate the owner or code accepts, so margin = target / lambda_C and the check holds
// while lambda_C is below the target (slabHolds, as every check).
std::optional<Check> riskCheck(const RiskCheckParts& r, const RiskSetPart& set,
                               std::vector<std::string>& notes) {
    const std::string id = riskCheckId(set.parameters.set);
    if (!set.risk) {
        notes.push_back(id + ": not checked: set " + std::to_string(set.parameters.set) +
                        " has no fitted collapse fragility (" + set.noFit +
                        "), so no annual rate of collapse follows from the study");
        return std::nullopt;
    }
    const double lambda = set.risk->integral.lambdaC;
    if (!(lambda > 0)) {
        notes.push_back(id + ": not checked: the annual rate of collapse is 0 to double "
                             "precision (the fragility's median lies far above the hazard "
                             "curve), so no margin is defined");
        return std::nullopt;
    }
    Check c;
    c.basis = CheckBasis::Risk;
    c.code = "risk_target";
    c.codeTitle = "target rate of collapse, " + riskTargetText(r.settings) +
                  (riskTargetText(r.settings) == "1 % in 50 years" ? " (ASCE 7-22 ch. 21)" : "");
    c.level = CheckLevel::Collapse;
    c.id = id;
    c.model = riskModelText(r, set);
    c.excitation = riskExcitationText(r);
    Comparison x;
    x.intensity = "annual rate";
    x.unit = kAnnualRateUnit;
    x.demandName = "lambda_C, annual rate of the slab falling (log-log interpolated hazard curve)";
    x.demand = lambda;
    x.capacityName = "target rate, " + riskTargetText(r.settings);
    x.capacity = r.settings.targetRate;
    x.searchLimit = r.settings.targetRate;
    x.margin = r.settings.targetRate / lambda;
    c.comparisons.push_back(x);
    finish(c);
    c.verdict = c.holds ? "meets the " + riskTargetText(r.settings) + " target"
                        : "exceeds the target rate (" + riskTargetText(r.settings) + ")";
    return c;
}

// Each block's checks; a note for a block that could not be checked, and for the blocks of a
// project without a record (the blocks stand on the building's floors under the ground record).
void addBlockChecks(const Project& p, const AssessmentParts& parts, Assessment& a) {
    if (!parts.blocks) {
        if (!p.blocks.empty() && !p.record)
            a.notes.push_back("blocks: the project's block checks need a ground record "
                              "(excitation.record); none ran");
        return;
    }
    for (const BlockCheckPart& b : *parts.blocks) {
        if (b.demands.empty())
            a.notes.push_back(blockCheckPrefix(b.block) +
                              ": not checked: no code of the project gives a floor demand "
                              "(codes.asce7_22 or codes.ec8)");
        for (Check& c : blockChecks(b, parts.recordName))
            a.checks.push_back(std::move(c));
    }
}

void pickGoverning(Assessment& a) {
    for (std::size_t k = 0; k < a.checks.size(); ++k)
        if (!a.governing || a.checks[k].governing().orderingMargin() <
                                a.checks[*a.governing].governing().orderingMargin())
            a.governing = k;
    if (!a.governing) return;
    const Check& c = a.checks[*a.governing];
    const Comparison& x = c.governing();
    std::ostringstream s;
    s.imbue(std::locale::classic());
    s << "the smallest margin of the " << a.checks.size() << " checks: ";
    const auto value = [&x](double v) {
        return x.unit == kAnnualRateUnit ? rateText(v) + " per year" : g(v) + " " + x.unit;
    };
    if (x.margin)
        s << x.capacityName << " = " << value(*x.capacity) << " against " << x.demandName << " = "
          << value(x.demand);
    else
        s << "no collapse up to the search limit (" << g(x.searchLimit) << " " << x.unit
          << "), margin above " << g(x.orderingMargin());
    a.governingReason = s.str();
}

} // namespace

std::string slabModelText(const Project& p, ModelKind model) {
    const std::string common = "mu = " + g(p.slab.slab.mu) + ", t* = " + g(p.slab.tstar) + " s";
    if (model == ModelKind::Planar)
        return "planar 2-DOF slab (Furgerson 1980 ch. VI), " + common +
               ", numerically integrated, f_y = " + g(p.planar.fyHz) +
               " Hz, A_y/A_x = " + g(p.planar.ayRatio) + ", theta = " + g(p.planar.theta) + ", " +
               verticalText(p.planar);
    const std::string solver =
        p.slab.solver == SolverKind::Exact ? "event-driven exact solver" : "the paper's RK4 solver";
    return "1-DOF slab (Furgerson 1980 ch. IV), " + common + ", " + solver;
}

std::string sineExcitationText(const Project& p) {
    return "enveloped sine '" + p.slab.envelope.name() + "' (alpha = " + g(p.slab.envelope.alpha) +
           "/s, beta = " + g(p.slab.envelope.beta) + "/s) at the building frequency f = 1/T";
}

std::string recordExcitationText(const Project& p, const std::string& recordName) {
    if (!p.record) return {};
    const RecordExcitation& e = *p.record;
    std::string s = "record " + recordName;
    if (e.floor)
        s += " through the floor filter (T = " + g(e.floor->period) +
             " s, zeta = " + g(e.floor->damping) + ")";
    else
        s += " driving the slab directly";
    return s + ", scaled to its critical peak";
}

std::string riskCheckId(std::size_t set) {
    return checkBasisName(CheckBasis::Risk) + ".set" + std::to_string(set);
}

std::string riskTargetText(const RiskSettings& s) {
    // The code's rate as a file spells it ("2.0101e-4", 5 digits) is the code's target.
    if (std::abs(s.targetRate / codeTargetRate() - 1) < 1e-4) return "1 % in 50 years";
    return rateText(s.targetRate) + " per year";
}

bool hasBasis(const Assessment& a, CheckBasis b) {
    for (const Check& c : a.checks)
        if (c.basis == b) return true;
    return false;
}

Assessment composeAssessment(const Project& p, const AssessmentParts& parts) {
    Assessment a;
    const double limit = p.critical.to;
    if (parts.sine) {
        const bool planar = p.model == ModelKind::Planar;
        const CheckBasis basis = planar ? CheckBasis::Planar : CheckBasis::Sine;
        for (const CodeVerdict& v : parts.sine->codes)
            a.checks.push_back(
                codeRatioCheck(basis, v, slabModelText(p, p.model), sineExcitationText(p),
                               "A_crit(f) at f = 1/T = " + g(v.frequencyHz) + " Hz", limit));
    }
    if (parts.record)
        for (const CodeVerdict& v : *parts.record)
            a.checks.push_back(codeRatioCheck(CheckBasis::Record, v,
                                              slabModelText(p, ModelKind::Slab1D),
                                              recordExcitationText(p, parts.recordName),
                                              "critical peak of the record's motion", limit));
    if (parts.floors)
        for (const FloorDemand& d : parts.floors->demands)
            a.checks.push_back(floorCheck(p, *parts.floors, d, parts.recordName, limit));
    else if (p.floors && !p.record)
        a.notes.push_back("floors: the project's floor check needs a ground record "
                          "(excitation.record); none ran");
    addBlockChecks(p, parts, a);
    if (parts.risk)
        for (const RiskSetPart& set : parts.risk->sets)
            if (std::optional<Check> c = riskCheck(*parts.risk, set, a.notes))
                a.checks.push_back(std::move(*c));
    if (p.study && p.study->hazard && p.study->results.empty())
        a.notes.push_back("risk: the study's hazard curve needs the study's results "
                          "(study.results, written by kinstab-cli study); no risk check ran");
    pickGoverning(a);
    return a;
}

} // namespace kinstab
