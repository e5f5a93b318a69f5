// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The sections of the design report, each added to the document only when its analysis ran.

#include "core/io/Project.h"
#include "report/ReportAnalysis.h"
#include "report/ReportDocument.h"

#include <QString>
#include <QStringList>

#include <optional>
#include <string>

namespace kinstab::report {

QString num(double x, int digits);
QString num(const std::optional<double>& x, int digits, const QString& none = QStringLiteral("—"));
// The one way the report prints a quantity, so that a value reads the same in every section
// (the CLI's JSON keeps full precision): accelerations (A_crit, peaks, code ratios) in g to
// 3 decimals; code coefficients to 4 significant digits without trailing zeros ("1", "0.075").
QString accelG(double g);
QString accelG(const std::optional<double>& g, const QString& none);
QString coefficient(double x);
inline QString qs(const std::string& s) {
    return QString::fromStdString(s);
}
// Lengths in the project's unit system (projectUnits, core/base/UnitSystem.h): the symbol, a
// value given in metres (to the millimetre, 0.1 mm for details, or 0.01 ft / in), and the
// building's own lengths (kept in its ft or m) converted to metres.
QString lengthSymbolOf(const Project& p, LengthScale scale);
QString lengthOf(const Project& p, double metres, LengthScale scale);
double buildingMetres(const Building& b, double v);
std::vector<double> levelHeightsShown(const Project& p); // levelHeights in the shown unit
QString scaleLabel(TauScale s); // "τ_max (peak of the envelope)", not the key tau_max

// Page 1 (FrontMatter.cpp): the revision table under the title block (the last three revisions),
// and after the verdict the signature/seal block (prepared by, checked by, engineer of record).
void addRevisions(ReportDocument& doc, const Project& p);
// The whole revision history, a section at the end, when page 1 lists only the last revisions.
void addRevisionHistory(ReportDocument& doc, const Project& p);
void addSignatureBlock(ReportDocument& doc, const Project& p);
// The disclaimer and what the margin means (FrontMatter.cpp); on page 1 with the verdict.
void addAcceptanceCriterion(ReportDocument& doc, const Project& p, const ReportAnalysis& a);
// The modelling assumptions that apply to this project, generated from it (AssumptionsSection.cpp).
void addAssumptionsSection(ReportDocument& doc, const Project& p, const ReportAnalysis& a);
// The symbols used, with meaning and unit (SymbolTable.cpp).
void addSymbolTable(ReportDocument& doc, const Project& p, const ReportAnalysis& a);
// The design-check detail; the verdict itself stays on page 1 (ResultSections.cpp).
void addCheckSection(ReportDocument& doc, const Project& p, const ReportAnalysis& a);
// Page 1: the one verdict and the excitation it rests on (SummarySection.cpp).
void addSummary(ReportDocument& doc, const Project& p, const ReportAnalysis& a);
// The assessment's checks as a table, one line each; the governing row in bold.
void addChecksTable(ReportDocument& doc, const Assessment& a);
// "event-driven exact solver ..." or "numerically integrated planar model ..., tolerance ...":
// the solver that actually ran the sweeps and the check.
QString solverDescription(const Project& p, const ReportAnalysis& a);
void addInputSections(ReportDocument& doc, const Project& p, const ReportAnalysis& a);
// "1-DOF friction-held slab ..." or "planar 2-DOF slab ..." (PlanarSection.cpp).
QString modelName(const Project& p);
void addPlanarInputs(ReportDocument& doc, const Project& p); // planar projects only
void addCodeSections(ReportDocument& doc, const Project& p, const ReportAnalysis& a);
void addExcitationSection(ReportDocument& doc, const Project& p, const ReportAnalysis& a);
void addSurfaceSections(ReportDocument& doc, const Project& p, const ReportAnalysis& a);
// Each code's top-floor ratio (UBC with and without F_t), frequency and A_crit of the check.
void addCodeCriticalTable(ReportDocument& doc, const ReportAnalysis& a);
// The record as the project's excitation (RecordSection.cpp): provenance, scaling, floor
// filter, the time histories and Fourier spectra of ground and floor (Figs. 25-27), the single
// run and the critical peak against the code ratios. Only when the analysis has a record.
void addRecordSection(ReportDocument& doc, const Project& p, const ReportAnalysis& a);
void addNumericsSection(ReportDocument& doc, const Project& p, const ReportAnalysis& a);
void addReferences(ReportDocument& doc, const Project& p, const ReportAnalysis& a);
// The floor-motion section (FloorsSection.cpp): only when the project has "floors" and a record.
void addFloorsSection(ReportDocument& doc, const Project& p, const ReportAnalysis& a);
// The free-standing blocks (BlocksSection.cpp): only when the project has blocks and a record.
void addBlocksSection(ReportDocument& doc, const Project& p, const ReportAnalysis& a);
// The rocking literature, when the blocks section shows (none otherwise).
QStringList blockCitations(const ReportAnalysis& a);
// The study section (StudySection.cpp): only when the project has a study. Throws ReportError
// naming study.spec or study.results when they cannot be read, or a study too large to run here.
void addStudySection(ReportDocument& doc, const Project& p, const ReportAnalysis& a);
// The risk section (RiskSection.cpp): only when the project's study names a hazard curve.
void addRiskSection(ReportDocument& doc, const Project& p, const ReportAnalysis& a);
// The closed forms' sources, when the risk section shows them (none otherwise).
QStringList riskCitations(const ReportAnalysis& a);
// The reference-list entries of the study's records (none without a study).
QStringList studyCitations(const Project& p);

} // namespace kinstab::report
