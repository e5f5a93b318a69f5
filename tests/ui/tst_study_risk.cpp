// SPDX-License-Identifier: GPL-3.0-or-later
// The Study tab's risk view (issue 33, docs/studies.md): for the example project
// paper-16-story-risk.json (its study's results on its hazard curve) every set's numbers are
// core's - those of kinstab-cli risk --results R --set K (core/risk/RiskReport.h), bit for bit -
// and the text shows them, with docs/studies.md's worked figures (risk.set0 1.93e-4 per year,
// margin 1.04; risk.set1 1.01e-4, margin 1.99); the three charts are drawn; a picked curve of
// another measure is refused naming both; the tab's jobs run on BackgroundJob (a study cleared
// while its results are read shows nothing of them).

#include "core/io/Project.h"
#include "core/risk/RiskReport.h"
#include "ui/RiskPanel.h"
#include "ui/StudyTab.h"

#include <QChart>
#include <QChartView>
#include <QFile>
#include <QTabWidget>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <filesystem>

using namespace kinstab;
using namespace kinstab::ui;

namespace {

const std::string kProject = KINSTAB_SOURCE_DIR "/resources/examples/paper-16-story-risk.json";

// Shows the project's study and waits for its results and then its risk.
bool showExample(StudyTab& tab, const Project& p) {
    QSignalSpy risk(tab.riskPanel(), &RiskPanel::finished);
    tab.showProjectStudy(
        p.study, QString::fromStdString(std::filesystem::path(kProject).parent_path().string()));
    return risk.wait(120000) && tab.riskPanel()->outcome().has_value();
}

nlohmann::ordered_json coreSet(const Project& p, std::size_t set) {
    RiskRequest r;
    r.hazard = p.study->hazard->file;
    r.results = p.study->results;
    r.set = set;
    return riskReport(r);
}

QString rate(double x) {
    return QString::number(x, 'e', 2);
}

} // namespace

class TestStudyRisk : public QObject {
    Q_OBJECT
private slots:
    void numbersAreCoresForTheExampleProject() {
        const Project p = loadProject(kProject);
        QVERIFY(p.study && p.study->hazard);
        StudyTab tab;
        QVERIFY2(showExample(tab, p), qPrintable(tab.riskPanel()->message()));
        const RiskOutcome& o = *tab.riskPanel()->outcome();
        QCOMPARE(o.sets.size(), std::size_t(2));
        for (std::size_t k = 0; k < o.sets.size(); ++k) {
            const nlohmann::ordered_json want = coreSet(p, k);
            const SetRisk& got = o.sets[k];
            QVERIFY(got.risk && got.bootstrap);
            QCOMPARE(got.risk->integral.lambdaC, want["lambda_c"].get<double>());
            QCOMPARE(got.risk->pInYears, want["p_collapse_in_years"]["p"].get<double>());
            QCOMPARE(got.risk->fragility.medianG, want["fragility"]["median_g"].get<double>());
            const nlohmann::ordered_json& boot = want["bootstrap"]["lambda_c"];
            QCOMPARE(got.bootstrap->lambdaC.p5, boot["p5"].get<double>());
            QCOMPARE(got.bootstrap->lambdaC.p50, boot["p50"].get<double>());
            QCOMPARE(got.bootstrap->lambdaC.p95, boot["p95"].get<double>());
            tab.riskPanel()->selectSet(static_cast<int>(k));
            const QString text = tab.riskPanel()->numbersText();
            QVERIFY2(text.contains(rate(want["lambda_c"].get<double>())), qPrintable(text));
            QVERIFY2(text.contains(rate(got.bootstrap->lambdaC.p95)), qPrintable(text));
            QVERIFY2(text.contains("P(collapse in 50 years)"), qPrintable(text));
        }
        // docs/studies.md, "A study in the project and its report": the assessment's figures.
        tab.riskPanel()->selectSet(0);
        QVERIFY(tab.riskPanel()->numbersText().contains("1.93e-04"));
        QVERIFY(tab.riskPanel()->numbersText().contains("1.04 (meets)"));
        tab.riskPanel()->selectSet(1);
        QVERIFY(tab.riskPanel()->numbersText().contains("1.01e-04"));
        QVERIFY(tab.riskPanel()->numbersText().contains("1.99 (meets)"));
        for (QChartView* v : {tab.riskPanel()->hazardView(), tab.riskPanel()->fragilityView(),
                              tab.riskPanel()->integrandView()})
            QVERIFY(!v->chart()->series().isEmpty());
    }
    void intensityOfInterestGivesPAtIt() {
        const Project p = loadProject(kProject);
        StudyTab tab;
        QVERIFY(showExample(tab, p));
        QSignalSpy again(tab.riskPanel(), &RiskPanel::finished);
        tab.riskPanel()->setIntensityOfInterest(0.6);
        QVERIFY(again.wait(120000));
        const SetRisk& s = tab.riskPanel()->outcome()->sets[0];
        QVERIFY(s.risk->pAtIm);
        QCOMPARE(*s.risk->pAtIm, collapseProbability(s.risk->fragility, 0.6));
        QVERIFY(tab.riskPanel()->numbersText().contains("P(C) at 0.6 g"));
    }
    void aCurveOfAnotherMeasureIsRefused() {
        const Project p = loadProject(kProject);
        StudyTab tab;
        QVERIFY(showExample(tab, p));
        QTemporaryDir dir;
        const QString sa = dir.filePath("sa.csv");
        QFile f(sa);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("# imt=SA(1.0)\nim_g,annual_rate\n0.1,1e-2\n1,1e-4\n");
        f.close();
        QSignalSpy done(tab.riskPanel(), &RiskPanel::finished);
        tab.riskPanel()->setHazardFile(sa);
        QVERIFY(done.wait(60000));
        QVERIFY(!tab.riskPanel()->outcome());
        const QString m = tab.riskPanel()->message();
        QVERIFY2(m.contains("sa.csv") && m.contains("PGA"), qPrintable(m));
    }
    void clearedWhileReadingShowsNothing() {
        const Project p = loadProject(kProject);
        StudyTab tab;
        QSignalSpy done(&tab, &StudyTab::finished);
        tab.showProjectStudy(p.study, QString());
        tab.clear(); // the read-back job is dropped: its results are of the study cleared
        QTest::qWait(300);
        QCOMPARE(done.count(), 0);
        QCOMPARE(tab.table()->rowCount(), 0);
        QVERIFY(!tab.isRunning()); // clear() waited for the worker
        QVERIFY(tab.rows().empty());
    }
};

QTEST_MAIN(TestStudyRisk)
#include "tst_study_risk.moc"
