// SPDX-License-Identifier: GPL-3.0-or-later
// A project as core's analysis request (core/assessment/ProjectRequest.h): the one builder behind
// kinstab-cli check, the report and the GUI's Run. The request holds the 1-DOF case once; the
// planar model adds only its own inputs, so μ and the envelope the planar runs use are the
// project's slab's. The expected values are the project's own inputs (paperExampleProject, the
// shipped paper-16-story.json) and runCodes of its building.

#include "core/analysis/RunAnalysis.h"
#include "core/assessment/ProjectRequest.h"
#include "core/base/InputError.h"
#include "core/codes/CodeSet.h"

#include <QtTest>

#include <stdexcept>

using namespace kinstab;

namespace {

AnalysisParts checkOnly() {
    AnalysisParts parts;
    parts.designCheck = true;
    return parts;
}

Project planarProject() {
    Project p = paperExampleProject();
    p.model = ModelKind::Planar;
    p.planar.vertical = VerticalSource::None; // gravity only: no record to read
    p.planar.fyHz = 0.2;
    p.planar.theta = 8.0;
    p.planar.ayRatio = 0.3;
    return p;
}

} // namespace

class TestProjectRequest : public QObject {
    Q_OBJECT
private slots:
    void oneDofProjectAsRequest() {
        const Project p = paperExampleProject();
        const AnalysisRequest q = analysisRequest(p, checkOnly());
        QVERIFY(!q.planar);
        QVERIFY(!q.planarCase());
        QCOMPARE(q.slab.slab.mu, p.slab.slab.mu);
        QCOMPARE(q.slab.tstar, p.slab.tstar);
        QCOMPARE(q.grid.amplitudes, p.grid.amplitudes);
        QCOMPARE(q.criticalFrequencies, p.grid.frequencies);
        QCOMPARE(q.checkSearch.tolerance, p.critical.tolerance);
        QCOMPARE(q.criticalSearch.to, p.critical.to);
        QVERIFY(q.parts.designCheck);
        QVERIFY(!q.parts.surface);
        const std::vector<CodeResult> codes = runCodes(p.building, p.codes);
        QVERIFY(!codes.empty());
        QCOMPARE(q.codes.size(), codes.size());
        for (std::size_t k = 0; k < codes.size(); ++k) {
            QCOMPARE(q.codes[k].code, codes[k].code);
            QCOMPARE(q.codes[k].topRatio, codes[k].topRatio);
        }
    }

    void planarInputsOnTheOneCase() {
        const Project p = planarProject();
        AnalysisRequest q = analysisRequest(p, checkOnly());
        QVERIFY(q.planar);
        QCOMPARE(q.planar->fyHz, 0.2);
        QCOMPARE(q.planar->theta, 8.0);
        QCOMPARE(q.planar->ayRatio, 0.3);
        QVERIFY(!q.planar->vertical);
        // μ lives once: the planar case the runs use takes the request's slab.
        QCOMPARE(q.planarCase()->common.slab.mu, p.slab.slab.mu);
        q.slab.slab.mu = 0.45;
        QCOMPARE(q.planarCase()->common.slab.mu, 0.45);
        QCOMPARE(q.planarCase()->params().mu, 0.45);
        QCOMPARE(q.planarCase()->params().theta, 8.0);
        QCOMPARE(q.planarCase()->tauRef(), q.slab.tauRef());
    }

    void planarProjectNeedsItsCase() {
        QVERIFY_THROWS_EXCEPTION(std::logic_error,
                                 analysisRequest(planarProject(), checkOnly(), std::nullopt));
        // A 1-DOF project ignores a planar case handed in.
        const Project p = paperExampleProject();
        QVERIFY(!analysisRequest(p, checkOnly(), PlanarCase{}).planar);
    }

    // The design check validates what its runs use: a planar input out of range is the
    // check's error (before any run), naming the input.
    void checkRefusesBadPlanarInput() {
        AnalysisRequest q = analysisRequest(planarProject(), checkOnly());
        q.planar->ayRatio = -1.0;
        AnalysisControl control;
        const AnalysisResult r = runAnalysis(q, control);
        QVERIFY(!r.check);
        QVERIFY(r.checkError);
        const QString message = QString::fromStdString(checkErrorMessage(r));
        QVERIFY2(message.contains(QStringLiteral("ay_ratio")), qPrintable(message));
        QCOMPARE(control.done(), std::size_t{1}); // the check's one step, no search run
    }
};

QTEST_APPLESS_MAIN(TestProjectRequest)
#include "tst_project_request.moc"
