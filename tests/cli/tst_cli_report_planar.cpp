// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli report --project with the planar model (issue #7, docs/user-guide.md): the report
// names the model and its inputs (f_y, A_y/A_x, Θ, normalization, the vertical record with RSN68 UP
// as the stand-in for the paper's Pacoima Dam vertical), and its A_crit is the planar one. Read
// back with poppler's pdftotext. The 1-DOF report is tst_cli_report's.

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QRegularExpression>
#include <QTemporaryDir>
#include <QtTest>

#include "CliRun.h"

#include <cmath>

namespace {

const QString kExample =
    QStringLiteral(KINSTAB_SOURCE_DIR "/resources/examples/paper-16-story.json");
const QString kRsn68Up =
    QStringLiteral(KINSTAB_SOURCE_DIR "/resources/records/RSN68_SFERN_PEL-UP.AT2");

// The paper's example project (mu 0.6, t* 0.099 s, moderate envelope, T = 1 s) as planar.
QByteArray planarProject(const QJsonObject& planar) {
    QFile f(kExample);
    if (!f.open(QIODevice::ReadOnly)) return {};
    QJsonObject j = QJsonDocument::fromJson(f.readAll()).object();
    j["model"] = "planar";
    j["planar"] = planar;
    return QJsonDocument(j).toJson();
}

QString pdfText(const QString& pdf) {
    const Run r = run("pdftotext", {"-layout", pdf, "-"});
    return r.code == 0 ? QString::fromUtf8(r.out) : QString();
}

} // namespace

class TestCliReportPlanar : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;
    QString text_;

    QString write(const QString& name, const QByteArray& content) {
        const QString path = dir_.filePath(name);
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly) || f.write(content) != content.size()) return {};
        return path;
    }

private slots:
    void initTestCase() {
        QVERIFY2(run("pdftotext", {"-v"}).code == 0,
                 "pdftotext missing: apt install poppler-utils");
        QVERIFY(dir_.isValid());
        const QString project = write("planar.json", planarProject({{"fy_hz", 1.0},
                                                                    {"ay_ratio", 0.9},
                                                                    {"theta", 20},
                                                                    {"normalization", "product"},
                                                                    {"vertical", "rsn68_up"}}));
        const QString pdf = dir_.filePath("planar.pdf");
        // A coarse figure grid: a planar point costs 2-5 ms of CPU.
        const Run r = cli({"report", "--project", project, "-o", pdf, "--figure-grid", "5"});
        QVERIFY2(r.code == 0, r.err.constData());
        text_ = pdfText(pdf);
        QVERIFY(!text_.isEmpty());
    }

    void statesModelAndInputs() {
        for (const char* s :
             {"planar 2-DOF slab with vertical motion (Furgerson 1980, ch. VI)", "Planar model",
              "come from the planar model", "Model: planar slab, f_y = 1.000 Hz"})
            QVERIFY2(text_.contains(QString::fromUtf8(s)), s);
        QVERIFY(QRegularExpression("frequency along the walls\\s+f_y\\s+1.000 Hz")
                    .match(text_)
                    .hasMatch());
        QVERIFY(QRegularExpression("A_y/A_x\\s+0.900").match(text_).hasMatch());
        QVERIFY(QRegularExpression("Θ\\s+20.00").match(text_).hasMatch());
        QVERIFY(QRegularExpression("normalization of S_max\\s+product").match(text_).hasMatch());
        QVERIFY(QRegularExpression("vertical motion\\s+a_z\\s+RSN68 UP").match(text_).hasMatch());
        // pdftotext -layout may break the note's line anywhere: compare without whitespace.
        QString flat = text_;
        flat.remove(QRegularExpression("\\s"));
        QVERIFY(flat.contains("RSN68)standsinforthepaper'sPacoimaDamvertical"));
        // The 1-DOF paper solver cross-check does not apply to the planar model.
        QVERIFY(!text_.contains("cross-check run time"));
    }

    // The verdict's A_crit at 1 Hz is the planar one, found independently by
    // `kinstab-cli critical --model planar` with the same case; chapter VI: below the 1-DOF
    // A_crit(1 Hz) of 0.95-1.00 (ch. V).
    void criticalAmplitudeIsPlanar() {
        const Run r =
            cli({"critical", "--model", "planar", "--fy", "1", "--ay-ratio", "0.9", "--theta", "20",
                 "--vertical", kRsn68Up, "--frequencies", "1", "--tolerance", "0.0001"});
        QVERIFY2(r.code == 0, r.err.constData());
        const double aCrit =
            QJsonDocument::fromJson(r.out).object()["a_crit"].toArray()[0].toDouble();
        QVERIFY(aCrit > 0.3 && aCrit < 0.95);
        const auto m =
            QRegularExpression("ATC 3-06 \\(1978\\) §4.2\\s+0.275\\s+1.000\\s+(\\d\\.\\d{3})\\s")
                .match(text_);
        QVERIFY2(m.hasMatch(), qPrintable(text_.left(3000)));
        // The report prints A_crit to 0.001 g.
        QCOMPARE_LE(std::abs(m.captured(1).toDouble() - aCrit), 1e-4 + 5e-4);
    }

    void badPlanarField_data() {
        QTest::addColumn<QByteArray>("planar");
        QTest::addColumn<QString>("message");
        QTest::newRow("negative f_y")
            << QByteArray(R"({"fy_hz": -1})")
            << "planar.fy_hz = -1 Hz: frequency along the walls must be between 0.001 and 1000 Hz";
        QTest::newRow("missing vertical file")
            << QByteArray(R"({"vertical": {"file": "/nonexistent/UP.AT2"}})")
            << "planar.vertical = '/nonexistent/UP.AT2'";
    }
    void badPlanarField() {
        QFETCH(QByteArray, planar);
        QFETCH(QString, message);
        const QString project =
            write("bad.json", planarProject(QJsonDocument::fromJson(planar).object()));
        const Run r = cli({"report", "--project", project, "-o", dir_.filePath("bad.pdf")});
        QCOMPARE(r.code, 2);
        QVERIFY2(QString::fromUtf8(r.err).contains(message), r.err.constData());
        QVERIFY(!QFile::exists(dir_.filePath("bad.pdf")));
    }
};

QTEST_GUILESS_MAIN(TestCliReportPlanar)
#include "tst_cli_report_planar.moc"
