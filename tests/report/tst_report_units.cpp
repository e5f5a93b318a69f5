// SPDX-License-Identifier: GPL-3.0-or-later
// The report prints lengths in the project's unit system (issue 35): a wall entered as 150 mm
// prints as 150 mm, not 5.9 in; the paper's building (in ft) prints in ft and in; a wall given
// by t* = 0.099 s prints the width Teaching and the Slab panel show (192.2 mm, 7.57 in).

#include "core/io/Project.h"
#include "report/ReportWriter.h"

#include "ReportReading.h"

#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

using namespace kinstab;
using namespace kinstab::report;

class TestReportUnits : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

    QString inputsText(const Project& p) {
        ReportSource s{p, "units.json", {}};
        s.sections = parseSections("inputs,symbols");
        const QString pdf = dir_.filePath("units.pdf");
        writeReport(s, computeReportAnalysis(p, quickAnalysis()), pdf, PaperSize::A4);
        return flat(pdfText(pdf));
    }

private slots:
    void initTestCase() {
        if (!havePdfToText()) QSKIP("pdftotext not installed");
    }

    void aWallIn_mmPrintsIn_mm() {
        Project p = loadProject(KINSTAB_SOURCE_DIR "/resources/examples/paper-16-story.json");
        p.wallWidthIn = 150.0 / 25.4; // typed as 150 mm in the GUI (stored in inches)
        p.slab.tstar = tstarFromWallWidthInches(*p.wallWidthIn);
        p.units = UnitSystem::SI;
        const QString t = inputsText(p);
        QVERIFY2(t.contains("wall width d 150 mm"), qPrintable(t));
        // 177 ft = 53.9496 m and 78.62 ft = 23.963 m, to the millimetre.
        QVERIFY(t.contains("h_n 53.95 m"));
        QVERIFY(t.contains("D 23.963 m"));
        QVERIFY(
            !t.contains(QRegularExpression(QStringLiteral("\\d in\\b")))); // no length in inches
    }

    void thePapersBuildingPrintsInFeetAndInches() {
        const Project p = loadProject(KINSTAB_SOURCE_DIR "/resources/examples/paper-16-story.json");
        QVERIFY(!p.units); // no "units": the building's ft gives US
        const QString t = inputsText(p);
        QVERIFY(t.contains("h_n 177 ft"));
        // t* = 0.099 s: d = 2 × 9.80665 × 0.099² m = 0.192234 m = 7.568 in.
        QVERIFY2(t.contains("wall width (from t*: d = 2g·t*²) d 7.57 in"), qPrintable(t));
    }
};

QTEST_MAIN(TestReportUnits)
#include "tst_report_units.moc"
