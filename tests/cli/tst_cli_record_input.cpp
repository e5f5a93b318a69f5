// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli with a record as the excitation (docs/theory.md §7; docs/user-guide.md "The command
// line"): simulate --record --critical (the critical scale, checked by re-running the CLI just
// above and below it), the planar model driven by records (against the 1-DOF record run when
// nothing moves along the walls), check --project with a record, and bad flags named with exit 2.

#include "CliRun.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>

namespace {
const QString kRecords = QStringLiteral(KINSTAB_SOURCE_DIR "/resources/records/");
const QString kElCentro = kRecords + "RSN6_IMPVALL.I_I-ELC180.AT2";

QJsonObject json(const Run& r) {
    return QJsonDocument::fromJson(r.out).object();
}

QString outcomeAt(double peak) {
    const Run r =
        cli({"simulate", "--record", kElCentro, "--amplitude", QString::number(peak, 'g', 17)});
    return json(r)["outcome"].toString();
}
} // namespace

class TestCliRecordInput : public QObject {
    Q_OBJECT
private slots:
    void criticalScale() {
        const Run r = cli({"simulate", "--record", kElCentro, "--critical", "--tolerance", "1e-6"});
        QCOMPARE(r.code, 0);
        const QJsonObject c = json(r)["critical"].toObject();
        const double peak = c["peak_g"].toDouble();
        QVERIFY2(peak > 0.6, r.out.constData()); // nothing slips below mu = 0.6
        QCOMPARE(c["scale_factor"].toDouble(), peak / c["motion_peak_g"].toDouble());
        // The search's own bracket, checked by separate runs of the scaled record.
        QCOMPARE(outcomeAt(peak), QString("collapsed"));
        QCOMPARE(outcomeAt(peak - 2e-6), QString("stable"));
    }
    void planarRecordIsOneDofWithoutAlongWallMotion_data() {
        QTest::addColumn<QStringList>("extra");
        QTest::newRow("El Centro at 1.5 g") << QStringList{"--amplitude", "1.5"};
        QTest::newRow("El Centro through the floor filter T 0.5 s, at 1.2 g")
            << QStringList{"--amplitude", "1.2", "--floor-period", "0.5"};
    }
    void planarRecordIsOneDofWithoutAlongWallMotion() {
        QFETCH(QStringList, extra);
        const Run one = cli(QStringList{"simulate", "--record", kElCentro} + extra);
        const Run two =
            cli(QStringList{"simulate", "--model", "planar", "--record", kElCentro} + extra);
        QCOMPARE(one.code, 0);
        QVERIFY2(two.code == 0, two.err.constData());
        const QJsonObject a = json(one), b = json(two);
        QCOMPARE(b["outcome"].toString(), a["outcome"].toString());
        QCOMPARE(b["outcome"].toString(), QString("collapsed"));
        const double ta = a["tau_c"].toDouble(), tb = b["tau_c"].toDouble();
        QCOMPARE_LE(std::abs(tb - ta), 1e-8 * ta);
        QCOMPARE(b["exit_side"].toString(), QString("across"));
        QVERIFY(b["record_y"].isNull());
    }
    void planarRecordWithSecondComponent() {
        const Run r =
            cli({"simulate", "--model", "planar", "--record", kRecords + "RSN68_SFERN_PEL090.AT2",
                 "--record-y", kRecords + "RSN68_SFERN_PEL180.AT2", "--vertical",
                 kRecords + "RSN68_SFERN_PEL-UP.AT2", "--amplitude", "0.9"});
        QVERIFY2(r.code == 0, r.err.constData());
        const QJsonObject j = json(r);
        QCOMPARE_GT(j["max_abs_delta_y"].toDouble(), 0.0);
        QCOMPARE(j["record_y"].toObject()["npts"].toInt(), 7945); // SOURCES.md: RSN68 PEL180
        QVERIFY(!j["vertical"].isNull());
    }
    void checkProjectWithRecord() {
        QTemporaryDir dir;
        QFile in(KINSTAB_SOURCE_DIR "/resources/examples/paper-16-story.json");
        QVERIFY(in.open(QIODevice::ReadOnly));
        QJsonObject p = QJsonDocument::fromJson(in.readAll()).object();
        p["excitation"] =
            QJsonObject{{"source", "record"}, {"record", QJsonObject{{"file", kElCentro}}}};
        const QString path = dir.filePath("p.json");
        QFile out(path);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(QJsonDocument(p).toJson());
        out.close();
        const Run r = cli({"check", "--project", path});
        QVERIFY2(r.code == 0, r.err.constData());
        const QJsonObject j = json(r);
        const double peak = j["critical_peak_g"].toDouble();
        const Run s = cli({"simulate", "--record", kElCentro, "--critical"});
        QCOMPARE_LE(std::abs(json(s)["critical"].toObject()["peak_g"].toDouble() - peak), 1e-12);
        // The paper's code ratios (0.140 with F_t left out; 0.275) are below it: overstress.
        const QJsonObject ubc = j["codes"].toObject()["ubc1976"].toObject();
        QCOMPARE(ubc["a_crit"].toDouble(), peak);
        QCOMPARE(ubc["verdict"].toString(), QString("overstress governs"));
    }
    void badFlags_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        QTest::newRow("critical without record")
            << QStringList{"simulate", "--amplitude", "1", "--frequency", "1", "--critical"}
            << "--critical: needs --record";
        QTest::newRow("scan step without critical")
            << QStringList{"simulate", "--record", kElCentro, "--scan-step", "0.1"}
            << "--scan-step 0.1: needs --critical";
        QTest::newRow("tolerance above scan step")
            << QStringList{"simulate", "--record", kElCentro, "--critical", "--tolerance", "0.5"}
            << "--tolerance 0.5";
        QTest::newRow("amplitude and scale factor")
            << QStringList{"simulate", "--record",       kElCentro, "--amplitude",
                           "1",        "--scale-factor", "2"}
            << "--scale-factor 2";
        QTest::newRow("negative scale factor")
            << QStringList{"simulate", "--record", kElCentro, "--scale-factor", "-2"}
            << "--scale-factor -2";
        QTest::newRow("record-y with the 1-DOF model")
            << QStringList{"simulate", "--record", kElCentro, "--record-y", kElCentro}
            << "--record-y";
        QTest::newRow("fy with planar record")
            << QStringList{"simulate", "--model", "planar", "--record", kElCentro, "--fy", "1"}
            << "--fy 1";
        QTest::newRow("missing y record")
            << QStringList{"simulate",           "--model", "planar",
                           "--record",           kElCentro, "--record-y",
                           kRecords + "none.AT2"}
            << "--record-y";
    }
    void badFlags() {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        const Run r = cli(args);
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains(message.toUtf8()), r.err.constData());
    }
};

QTEST_APPLESS_MAIN(TestCliRecordInput)
#include "tst_cli_record_input.moc"
