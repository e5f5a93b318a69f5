// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A project's assessment: every check the project implies, each with what it compares, its
// margin and its verdict, and the governing check (the smallest margin). Composed here once from
// the analyses that ran; `kinstab-cli check`, the report's page 1, the GUI's verdict table and
// Python's kinstab.assess all show this and compose no verdict of their own (docs/assessment.md).
//
// Which checks a project implies:
// - sine.CODE   each code's top-floor ratio against A_crit(1/T) of the 1-DOF slab under the
//               enveloped sine (Furgerson 1980 ch. V), or planar.CODE with the planar model
//               (ch. VI) when the project's model is planar;
// - record.CODE each code's top-floor ratio against the critical peak of the project's record
//               (when it has one);
// - floors.CODE.LEVEL the slab on its level of the building's shear-building model under the
//               ground record, against ASCE 7-22 §13.3.1 (design, MCE_R) and EN 1998-1 §4.3.5.2
//               (when the project has "floors" and a record);
// - risk.setK   per parameter set K of the project's study (numbered from 0, as kinstab-cli risk
//               --set K), the annual rate of the slab falling lambda_C (the set's fitted
//               fragility against the study's hazard curve) against the target rate (when the
//               study has results and a hazard curve; core/assessment/RiskCheck.h);
// - block.NAME.CODE.LEVEL per free-standing block of the project's "blocks", the ground PGA at
//               which it overturns on its level against the same code levels as the floor
//               checks (when the project has a record; core/assessment/BlockCheck.h).

#include "core/assessment/BlockCheck.h"
#include "core/assessment/Check.h"
#include "core/assessment/RiskCheck.h"
#include "core/base/ModelKind.h"
#include "core/building/LevelCritical.h"
#include "core/check/DesignCheck.h"
#include "core/codes/FloorDemand.h"

#include <optional>
#include <string>
#include <vector>

namespace kinstab {

struct Project;

// The floor analysis at the slab's level: what the floors checks need.
struct FloorCheckParts {
    std::vector<FloorDemand> demands; // asce7_22, asce7_22_mce, ec8 (those the project selects)
    LevelCritical atSlab;             // the critical ground PGA and floor peak at the slab's level
    double pga = 0;                   // g, |peak| of the ground record as given
    int stories = 0;
};

// What ran for the project: each part present when it ran.
struct AssessmentParts {
    std::optional<DesignCheckResult> sine;          // of the project's model (planar when planar)
    std::optional<std::vector<CodeVerdict>> record; // against the record's critical peak
    std::string recordName;                         // the ground record's name
    std::optional<FloorCheckParts> floors;
    std::optional<RiskCheckParts> risk;                // the study's sets against its hazard curve
    std::optional<std::vector<BlockCheckPart>> blocks; // the project's blocks, searched
};

struct Assessment {
    std::vector<Check> checks;
    std::optional<std::size_t> governing; // index into checks: the smallest margin
    std::string governingReason;          // why it governs, in words
    std::vector<std::string> notes;       // checks the project implies that could not run

    const Check* governingCheck() const { return governing ? &checks.at(*governing) : nullptr; }
};

bool hasBasis(const Assessment& a, CheckBasis b);

// Composes the assessment from the parts that ran. Pure: runs nothing.
Assessment composeAssessment(const Project& p, const AssessmentParts& parts);

// The model each check of a basis rests on, in words (also the report's and the GUI's labels).
std::string slabModelText(const Project& p, ModelKind model);
std::string sineExcitationText(const Project& p);
std::string recordExcitationText(const Project& p, const std::string& recordName);
// "risk.set0": the risk check of a parameter set (numbered from 0, as kinstab-cli risk --set).
std::string riskCheckId(std::size_t set);
// "1 % in 50 years" for the code's rate at 50 years; else the rate itself, "5e-05 per year".
std::string riskTargetText(const RiskSettings& s);

} // namespace kinstab
