// SPDX-License-Identifier: GPL-3.0-or-later
// One verdict per report (issue 13), read back with poppler's pdftotext. The record example
// resources/examples/paper-16-story-record.json: page 1 says the verdict rests on the record,
// gives the record's critical peak (the number core's record analysis finds, the GUI's) with
// "collapsed at the record as given" explained beside it, and the enveloped-sine check only as
// a labelled secondary line. A planar project's report names the numerically integrated model
// and its tolerance, never the exact closed-form solver. Needs poppler-utils.

#include "core/check/RecordAnalysis.h"
#include "core/io/Project.h"
#include "report/ReportWriter.h"

#include "ReportReading.h"

#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

using namespace kinstab;
using namespace kinstab::ui::report;

class TestReportVerdict : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        if (!havePdfToText()) QSKIP("pdftotext not installed");
    }

    void recordProjectHasOneVerdictOnPageOne() {
        const Project p =
            loadProject(KINSTAB_SOURCE_DIR "/resources/examples/paper-16-story-record.json");
        const ReportAnalysis a = computeReportAnalysis(p, quickAnalysis());
        QVERIFY(a.record && a.record->critical && a.record->critical->peak);
        const QString pdf = dir_.filePath("record.pdf");
        QVERIFY(writeReport({p, "paper-16-story-record.json", {}}, a, pdf, PaperSize::A4) > 1);
        const QString page1 = flat(pdfText(pdf, 1, 1));

        // Independent of the report: the record's critical peak straight from core.
        RecordAnalysisInput in{p.slab, *p.record, p.critical, a.codes, true, false};
        const RecordAnalysis ref = analyseRecord(in);
        QVERIFY(ref.critical && ref.critical->peak);
        const QString peak = QString::number(*ref.critical->peak, 'f', 3); // accelG: 0.001 g
        QVERIFY2(page1.contains("Verdict basis: the recorded excitation"), qPrintable(page1));
        QVERIFY2(page1.contains("the critical peak is " + peak + " g"), qPrintable(page1));
        // The run at the record as given collapses (the record's peak exceeds the critical
        // one), explained beside the critical peak.
        QCOMPARE(int(ref.run.outcome), int(Outcome::Collapsed));
        QVERIFY(ref.peak > *ref.critical->peak);
        QVERIFY2(page1.contains("collapses at the record as given (scale 1.0, peak " +
                                QString::number(ref.peak, 'f', 3) + " g)"),
                 qPrintable(page1));
        QVERIFY(
            page1.contains("through the floor filter of the building (T = 1.000 s, ζ = 0.020)"));
        // One verdict: the record's; the sine's A_crit only on the labelled secondary line.
        QCOMPARE(page1.count("Verdict basis"), 1);
        QCOMPARE(page1.count("Secondary check, enveloped sine (for comparison; not the verdict)"),
                 1);
        const QString sineACrit = QString::number(*a.check.codes.front().aCrit, 'f', 3);
        const qsizetype secondary = page1.indexOf("Secondary check");
        QVERIFY(page1.indexOf(sineACrit) >= secondary); // only after the secondary label
        QVERIFY(!page1.contains("Verdict basis: the enveloped sine"));

        // Further on, the sine's design check is labelled as the comparison it is.
        const QString all = flat(pdfText(pdf, 1, 99));
        QVERIFY(all.contains("Design check with the enveloped sine"));
        QVERIFY(all.contains("For comparison only: the verdict of this report rests on the "
                             "project's record"));
    }

    void sineProjectNamesItsBasis() {
        const Project p = loadProject(KINSTAB_SOURCE_DIR "/resources/examples/paper-16-story.json");
        const ReportAnalysis a = computeReportAnalysis(p, quickAnalysis());
        const QString pdf = dir_.filePath("sine.pdf");
        QVERIFY(writeReport({p, "paper-16-story.json", {}}, a, pdf, PaperSize::A4) > 1);
        const QString page1 = flat(pdfText(pdf, 1, 1));
        QVERIFY2(page1.contains("Verdict basis: the enveloped sine"), qPrintable(page1));
        QVERIFY(!page1.contains("Secondary check"));
        QVERIFY(!page1.contains("recorded excitation"));
    }

    void planarReportNamesTheNumericalSolver() {
        Project p = loadProject(KINSTAB_SOURCE_DIR "/resources/examples/paper-16-story.json");
        p.model = ModelKind::Planar;
        p.slab.solver = SolverKind::Exact; // what the 1-DOF slab would use; planar ignores it
        p.grid = {{0.9, 1.0}, {0.9, 1.1}};
        p.critical.scanStep = 0.05;
        p.critical.tolerance = 1e-3;
        const ReportAnalysis a = computeReportAnalysis(p, quickAnalysis());
        QVERIFY(a.planarSolver.has_value());
        const QString pdf = dir_.filePath("planar.pdf");
        QVERIFY(writeReport({p, "planar.json", {}}, a, pdf, PaperSize::A4) > 1);
        const QString all = flat(pdfText(pdf, 1, 99));
        const QString tol = QString::number(a.planarSolver->relTol, 'g', 3);
        QVERIFY2(all.contains("numerically integrated planar model"), qPrintable(all));
        QVERIFY(all.contains("tolerance " + tol + " relative"));
        QVERIFY(all.contains("numerical (Dormand–Prince 5(4), tolerance " + tol + ")"));
        QVERIFY(!all.contains("event-driven exact solver"));
        QVERIFY(!QRegularExpression("solver\\s+exact\\b").match(all).hasMatch());
    }
};

QTEST_MAIN(TestReportVerdict)
#include "tst_report_verdict.moc"
