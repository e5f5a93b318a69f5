// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli report for a project whose excitation is a record (docs/theory.md §7;
// docs/user-guide.md): the example project resources/examples/paper-16-story-record.json (the
// paper's building under the 1971 Pacoima Dam record through the building's floor filter), read
// back with pdftotext. The critical peak printed must be the one kinstab-cli simulate --record
// --critical computes. Needs poppler-utils.

#include "CliRun.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

namespace {
const QString kProject =
    QStringLiteral(KINSTAB_SOURCE_DIR "/resources/examples/paper-16-story-record.json");
const QString kRecord =
    QStringLiteral(KINSTAB_SOURCE_DIR "/resources/records/RSN77_SFERN_PUL164.AT2");
} // namespace

class TestCliReportRecord : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString text_;

private slots:
    void initTestCase() {
        QVERIFY2(run("pdftotext", {"-v"}).code == 0,
                 "pdftotext missing: apt install poppler-utils");
        const QString pdf = dir_.filePath("record.pdf");
        const Run r = cli({"report", "--project", kProject, "-o", pdf, "--figure-grid", "9"});
        QVERIFY2(r.code == 0, r.err.constData());
        const Run t = run("pdftotext", {"-layout", pdf, "-"});
        QCOMPARE(t.code, 0);
        text_ = QString::fromUtf8(t.out);
    }
    void provenanceScalingAndFilter() {
        QVERIFY(text_.contains("Recorded excitation"));
        QVERIFY(text_.contains("RSN77_SFERN_PUL164.AT2 (PEER AT2)") ||
                text_.contains("RSN77_SFERN_PUL164.AT2"));
        QVERIFY(text_.contains("San Fernando"));
        QVERIFY(text_.contains("4172 at")); // NPTS of the AT2 header (SOURCES.md)
        QVERIFY(text_.contains("T = 1.000 s, ζ = 0.020"));
        QVERIFY(text_.contains("Figs. 25–26"));
        QVERIFY(text_.contains("(Fig. 27)"));
    }
    void criticalPeakIsTheCliOne() {
        const Run s = cli({"simulate", "--record", kRecord, "--floor-period", "1", "--critical"});
        QCOMPARE(s.code, 0);
        const QJsonObject j = QJsonDocument::fromJson(s.out).object();
        const double peak = j["critical"].toObject()["peak_g"].toDouble();
        const QString shown = QString::number(peak, 'f', 3); // the report prints g to 0.001
        QVERIFY2(text_.contains(shown + " g (factor"), qPrintable(shown));
        QVERIFY(text_.contains("ratio against the record's"));
        QVERIFY(text_.contains("record.ubc1976"));
        // The outcome of the single run as recorded (factor 1) is the CLI's too.
        QVERIFY(text_.contains(j["outcome"].toString()));
        QVERIFY(text_.contains("At the record as given"));
    }
};

QTEST_APPLESS_MAIN(TestCliReportRecord)
#include "tst_cli_report_record.moc"
