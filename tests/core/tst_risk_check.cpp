// SPDX-License-Identifier: GPL-3.0-or-later
// The assessment's risk checks (core/assessment/RiskCheck.h, docs/assessment.md): a project whose
// study has results and a hazard curve has one check risk.setK per parameter set, whose demand is
// lambda_C as `kinstab-cli risk --results R --set K` computes it (riskReport, the command's own
// core function, on the same files), whose capacity is the project's target rate and whose
// margin is target / lambda_C: tightened below lambda_C it fails, loosened above it holds. A set
// without a fitted fragility is said to be unchecked, with no number; the hazard block is
// validated naming the field, and a project with a hazard curve but no results says so.

#include "core/assessment/AssessmentJson.h"
#include "core/assessment/RunAssessment.h"
#include "core/base/InputError.h"
#include "core/io/Project.h"
#include "core/risk/RiskReport.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <filesystem>
#include <fstream>

using namespace kinstab;

namespace {

const std::string kExamples = KINSTAB_SOURCE_DIR "/resources/examples/";

Project riskExample() {
    return loadProject(kExamples + "paper-16-story-risk.json");
}

const Check* findCheck(const Assessment& a, const std::string& id) {
    for (const Check& c : a.checks)
        if (c.id == id) return &c;
    return nullptr;
}

// The risk checks alone, composed as runAssessment composes them.
Assessment riskAssessment(const Project& p) {
    AssessmentParts parts;
    parts.risk = projectRiskParts(p);
    return composeAssessment(p, parts);
}

// The message loading the example's study with its "hazard" replaced gives, or else reading
// its curve as the assessment does ("" when both succeed).
std::string hazardError(const nlohmann::json& hazard) {
    nlohmann::json j = projectToJson(paperExampleProject());
    j["study"] = {{"spec", "study-example.json"}, {"hazard", hazard}};
    try {
        const Project p = parseProject(j.dump(), kExamples);
        (void)readProjectHazard(*p.study);
    } catch (const ProjectError& e) {
        return e.what();
    } catch (const InputError& e) {
        return e.what();
    }
    return {};
}

bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

} // namespace

class TestRiskCheck : public QObject {
    Q_OBJECT

private slots:
    void exampleNamesTheHazardBesideTheProject() {
        const Project p = riskExample();
        QVERIFY(p.study && p.study->hazard);
        QCOMPARE(std::filesystem::path(p.study->hazard->file).filename().string(),
                 std::string("hazard-second-order.csv"));
        QVERIFY(std::filesystem::path(p.study->hazard->file).is_absolute());
        QVERIFY(!p.study->hazard->targetRate); // none: the code's
        QCOMPARE(riskSettingsOf(*p.study->hazard).targetRate, codeTargetRate());
        QCOMPARE(p.study->hazard->years, 50.0);
        // Written back relative to the project's folder, with every key, and read back equal.
        const nlohmann::json j = projectToJson(p, kExamples);
        QCOMPARE(j["study"]["hazard"]["file"].get<std::string>(),
                 std::string("hazard-second-order.csv"));
        QCOMPARE(j["study"]["hazard"]["format"].get<std::string>(), std::string("auto"));
        QVERIFY(projectFromJson(j, kExamples).study == p.study);
    }

    // The demand of risk.setK is lambda_c of kinstab-cli risk --results R --set K on the same
    // hazard file and results (riskReport is that command's core function).
    void demandIsTheRiskCommandsLambdaC() {
        const Project p = riskExample();
        AnalysisControl control;
        const AssessmentRun run = runAssessment(p, std::nullopt, control);
        QVERIFY(run.parts.risk.has_value());
        QCOMPARE(run.parts.risk->sets.size(), std::size_t(2)); // mu = 0.4 and 0.6
        for (std::size_t set = 0; set < 2; ++set) {
            RiskRequest r;
            r.hazard = p.study->hazard->file;
            r.results = p.study->results;
            r.set = set;
            const nlohmann::ordered_json cli = riskReport(r);
            const Check* c = findCheck(run.assessment, riskCheckId(set));
            QVERIFY2(c, riskCheckId(set).c_str());
            const Comparison& x = c->governing();
            QCOMPARE(x.demand, cli["lambda_c"].get<double>());
            QCOMPARE(*x.capacity, codeTargetRate());
            QCOMPARE(*x.margin, codeTargetRate() / x.demand);
            QCOMPARE(x.unit, std::string("1/yr"));
            QCOMPARE(x.intensity, std::string("annual rate"));
            QCOMPARE(c->basis, CheckBasis::Risk);
            QCOMPARE(c->level, CheckLevel::Collapse);
            QVERIFY(contains(c->excitation, "hazard-second-order.csv"));
            QVERIFY(contains(c->model, "study set " + std::to_string(set)));
            QCOMPARE(c->verdict, std::string(c->holds ? "meets the 1 % in 50 years target"
                                                      : "exceeds the target rate (1 % in 50 "
                                                        "years)"));
        }
        // It governs like any other check: the governing check has the smallest margin.
        const Check* g = run.assessment.governingCheck();
        QVERIFY(g);
        for (const Check& c : run.assessment.checks)
            QVERIFY(g->governing().orderingMargin() <= c.governing().orderingMargin());
        const std::string json = assessmentJson(run.assessment).dump();
        QVERIFY(!contains(json, "NaN") && !contains(json, "null,\"margin_at_least\":null"));
    }

    // The target tightened to half of lambda_C fails the check (margin 0.5); loosened to twice
    // lambda_C it holds (margin 2): the margin is target / lambda_C and nothing else.
    void targetBelowLambdaFailsAboveHolds() {
        Project p = riskExample();
        const double lambda = findCheck(riskAssessment(p), "risk.set0")->governing().demand;
        QVERIFY(lambda > 0);
        for (const double factor : {0.5, 2.0}) {
            p.study->hazard->targetRate = factor * lambda;
            const Assessment a = riskAssessment(p);
            const Check* c = findCheck(a, "risk.set0");
            QVERIFY(c);
            QCOMPARE(c->governing().demand, lambda);
            QCOMPARE_LT(std::abs(*c->governing().margin - factor), 1e-12);
            QCOMPARE(c->holds, factor > 1);
            QVERIFY(contains(c->verdict, factor > 1 ? "meets the " : "exceeds the target rate"));
            // Not the code's target any more: the rate itself is named.
            QVERIFY(contains(c->verdict, "per year"));
            if (factor < 1) {
                QCOMPARE(a.governingCheck()->holds, false);
            }
        }
    }

    // A set without a fitted fragility (no record collapsed the slab) has no risk check and no
    // number: a note says why; the other set is checked.
    void unfittedSetIsANoteNotANumber() {
        const Project p = riskExample();
        const HazardCurve curve = readProjectHazard(*p.study);
        std::vector<StudyRow> rows;
        for (std::size_t k = 0; k < 6; ++k) {
            StudyRow r;
            r.index = k;
            r.set = k < 3 ? 0 : 1;
            r.record = "r" + std::to_string(k % 3);
            r.measure = "pga";
            r.limitIntensity = 3;
            if (r.set == 0) r.criticalIntensity = 0.5 + 0.2 * double(k); // three collapses
            rows.push_back(r);
        }
        AssessmentParts parts;
        parts.risk = riskCheckParts(*p.study->hazard, curve, rows);
        const Assessment a = composeAssessment(p, parts);
        QVERIFY(findCheck(a, "risk.set0"));
        QVERIFY(!findCheck(a, "risk.set1"));
        bool said = false;
        for (const std::string& n : a.notes)
            said = said || (contains(n, "risk.set1: not checked") && contains(n, "no fitted"));
        QVERIFY(said);
    }

    void hazardWithoutResultsIsANote() {
        Project p = riskExample();
        p.study->results.clear();
        QVERIFY(!projectRiskParts(p).has_value());
        const Assessment a = composeAssessment(p, {});
        QCOMPARE(a.notes.size(), std::size_t(1));
        QVERIFY(contains(a.notes.front(), "study.results"));
    }

    void badHazardBlockNamesTheField_data() {
        QTest::addColumn<QString>("hazard");
        QTest::addColumn<QString>("expected");
        QTest::newRow("no file") << R"({"format": "csv"})"
                                 << "study.hazard.file";
        QTest::newRow("missing file") << R"({"file": "no-such-hazard.csv"})"
                                      << "study.hazard.file = '";
        QTest::newRow("format") << R"({"file": "hazard-second-order.csv", "format": "xls"})"
                                << "study.hazard.format";
        QTest::newRow("site") << R"({"file": "hazard-second-order.csv", "site": [1]})"
                              << "study.hazard.site";
        QTest::newRow("latitude") << R"({"file": "hazard-second-order.csv", "site": [0, 91]})"
                                  << "study.hazard.site";
        QTest::newRow("target") << R"({"file": "hazard-second-order.csv", "target_rate": 0})"
                                << "study.hazard.target_rate";
        QTest::newRow("years") << R"({"file": "hazard-second-order.csv", "years": -1})"
                               << "study.hazard.years";
        QTest::newRow("not a curve") << R"({"file": "study-example.json"})"
                                     << "study.hazard.file = '";
    }

    void badHazardBlockNamesTheField() {
        QFETCH(QString, hazard);
        QFETCH(QString, expected);
        const std::string e = hazardError(nlohmann::json::parse(hazard.toStdString()));
        QVERIFY2(contains(e, expected.toStdString()), e.c_str());
    }

    // A curve of another measure than the study's (pga) is refused at load, naming the field.
    void curveOfAnotherMeasureIsRefused() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const std::string path = dir.filePath("sa1.csv").toStdString();
        std::ofstream(path) << "# imt=SA(1.0)\nim_g,annual_rate\n0.1,0.01\n1,0.0001\n";
        const std::string e = hazardError({{"file", path}});
        QVERIFY2(contains(e, "study.hazard.file = '") && contains(e, "SA"), e.c_str());
    }

    // core/risk takes the format names and the years' limit from io's declaration.
    void ioNamesAgreeWithRisk() {
        std::vector<std::string> names;
        for (const char* n : kProjectHazardFormats)
            names.push_back(n);
        const std::vector<std::string> risk = {
            hazardFormatName(HazardFormat::Auto), hazardFormatName(HazardFormat::OpenQuake),
            hazardFormatName(HazardFormat::Usgs), hazardFormatName(HazardFormat::Csv)};
        QVERIFY(names == risk);
        QCOMPARE(kMaxProjectHazardYears, kMaxRiskYears);
    }

    // Every optional key in range (a site is for an OpenQuake file only: a CSV holds one site).
    void goodHazardBlockLoads() {
        const std::string e = hazardError(nlohmann::json::parse(
            R"({"file": "hazard-second-order.csv", "format": "csv", "target_rate": 1e-4,
                "years": 100})"));
        QVERIFY2(e.empty(), e.c_str());
    }

    void siteOfACsvCurveIsRefused() {
        const std::string e = hazardError(
            nlohmann::json::parse(R"({"file": "hazard-second-order.csv", "site": [-118.2, 34]})"));
        QVERIFY2(contains(e, "study.hazard.file = '") && contains(e, "site"), e.c_str());
    }
};

QTEST_APPLESS_MAIN(TestRiskCheck)
#include "tst_risk_check.moc"
