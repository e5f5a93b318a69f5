// SPDX-License-Identifier: GPL-3.0-or-later
// One assessment per report (issues 13, 30), read back with poppler's pdftotext. The record
// example resources/examples/paper-16-story-record.json: page 1 lists the sine's and the record's
// checks, the record's against the critical peak core's record analysis finds (the GUI's), with
// "falls at the record as given" explained beside them, and one governing check. A planar project's
// report names the numerically integrated model and its tolerance, never the exact closed-form
// solver. Needs poppler-utils.

#include "core/check/RecordAnalysis.h"
#include "core/io/Project.h"
#include "report/ReportWriter.h"

#include "ReportReading.h"

#include <QProcess>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

using namespace kinstab;
using namespace kinstab::report;

class TestReportVerdict : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void initTestCase() {
        if (!havePdfToText()) QSKIP("pdftotext not installed");
    }

    void recordProjectListsEveryCheckOnPageOne() {
        const Project p =
            loadProject(KINSTAB_SOURCE_DIR "/resources/examples/paper-16-story-record.json");
        const ReportAnalysis a = computeReportAnalysis(p, quickAnalysis());
        QVERIFY(a.record && a.record->critical && a.record->critical->peak);
        const QString pdf = dir_.filePath("record.pdf");
        QVERIFY(writeReport({p, "paper-16-story-record.json", {}}, a, pdf, PaperSize::A4) > 1);
        const QString page1 = flat(pdfText(pdf, 1, 1));

        // Independent of the report: the record's critical peak straight from core.
        RecordAnalysisInput in{p.slab, *p.record, p.critical, a.codes, true};
        const RecordAnalysis ref = analyseRecord(in);
        QVERIFY(ref.critical && ref.critical->peak);
        const QString peak = QString::number(*ref.critical->peak, 'f', 3); // accelG: 0.001 g
        // The project's checks: the enveloped sine's and the record's, one row each, the record
        // rows against the critical peak core finds.
        QCOMPARE(a.assessment.checks.size(), 2 * a.codes.size());
        for (const Check& c : a.assessment.checks) {
            QVERIFY2(page1.contains(QString::fromStdString(c.id)), qPrintable(page1));
            if (c.basis == CheckBasis::Record)
                QCOMPARE(QString::number(*c.governing().capacity, 'f', 3), peak);
        }
        QVERIFY2(page1.contains(" " + peak + " "), qPrintable(page1));
        QVERIFY(page1.contains("Governing check: " +
                               QString::fromStdString(a.assessment.governingCheck()->id)));
        // The run at the record as given collapses (its peak exceeds the critical one),
        // explained beside the checks.
        QCOMPARE(int(ref.run.outcome), int(Outcome::Collapsed));
        QVERIFY(ref.peak > *ref.critical->peak);
        const QString summary = flat(pdfText(pdf, 1, 2)); // the summary's notes run onto page 2
        QVERIFY2(summary.contains("At the record as given (peak " +
                                  QString::number(ref.peak, 'f', 3) +
                                  " g under the slab) the slab falls"),
                 qPrintable(summary));
        QVERIFY(summary.contains("through the floor filter (T = 1 s, zeta = 0.02)"));
        QCOMPARE(page1.count("Governing check"), 1);
    }

    void sineProjectNamesItsBasis() {
        const Project p = loadProject(KINSTAB_SOURCE_DIR "/resources/examples/paper-16-story.json");
        const ReportAnalysis a = computeReportAnalysis(p, quickAnalysis());
        const QString pdf = dir_.filePath("sine.pdf");
        QVERIFY(writeReport({p, "paper-16-story.json", {}}, a, pdf, PaperSize::A4) > 1);
        const QString page1 = flat(pdfText(pdf, 1, 1));
        QVERIFY2(page1.contains("the enveloped sine (Furgerson 1980, ch. IV–V)"),
                 qPrintable(page1));
        QVERIFY(page1.contains("Governing check: sine."));
        QVERIFY(!page1.contains("record."));
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
