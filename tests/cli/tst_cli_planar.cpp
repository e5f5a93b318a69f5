// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli with --model planar (docs/user-guide.md "The command line"), run as a user would.

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QtTest>

#include "CliRun.h"

class TestCliPlanar : public QObject {
    Q_OBJECT
private slots:
    void simulateAlongWallExit();
    void simulateOneDofLimitMatchesSlab1d();
    void surfaceWithVerticalRecord();
    void badInputExitsTwo_data();
    void badInputExitsTwo();
};

namespace {

QJsonObject json(const Run& r) {
    return QJsonDocument::fromJson(r.out).object();
}
} // namespace

// docs/theory.md §5: gravity only, f_y 0.2 Hz, f_x 2 Hz, A_x 0.9 leaves along the walls.
void TestCliPlanar::simulateAlongWallExit() {
    const Run r = cli({"simulate", "--model", "planar", "--amplitude", "0.9", "--frequency", "2",
                       "--fy", "0.2", "--events"});
    QCOMPARE(r.code, 0);
    const QJsonObject j = json(r);
    QCOMPARE(j["model"].toString(), QString("planar"));
    QCOMPARE(j["outcome"].toString(), QString("collapsed"));
    QCOMPARE(j["exit_side"].toString(), QString("along"));
    QVERIFY(j["tau_lift_off"].isNull());
    QCOMPARE_LT(std::abs(j["max_abs_delta_y"].toDouble() - 20.0), 1e-9); // theta, default 20
    QCOMPARE(j["events"].toArray().last().toObject()["kind"].toString(), QString("collapse"));
    QVERIFY(j["work"].toObject()["steps"].toInt() > 0);
}

// With --ay-ratio 0 the planar model is the 1-DOF model: same outcome and tau_c (1e-8).
void TestCliPlanar::simulateOneDofLimitMatchesSlab1d() {
    const QStringList common{"simulate", "--amplitude", "1.0", "--frequency", "1"};
    const Run one = cli(common);
    const Run planar =
        cli(common + QStringList{"--model", "planar", "--fy", "0.5", "--ay-ratio", "0"});
    QCOMPARE(one.code, 0);
    QCOMPARE(planar.code, 0);
    const double a = json(one)["tau_c"].toDouble(), b = json(planar)["tau_c"].toDouble();
    QCOMPARE(json(planar)["exit_side"].toString(), QString("across"));
    QCOMPARE_LT(std::abs(a - b), 1e-8 * a);
}

void TestCliPlanar::surfaceWithVerticalRecord() {
    const QString vertical =
        QString(KINSTAB_SOURCE_DIR) + "/resources/records/RSN68_SFERN_PEL-UP.AT2";
    const Run r = cli({"surface", "--model", "planar", "--amplitudes", "0.6,1.1", "--frequencies",
                       "1,2", "--fy", "0.5", "--vertical", vertical, "--threads", "1"});
    QCOMPARE(r.code, 0);
    const QJsonObject j = json(r);
    QCOMPARE(j["model"].toString(), QString("planar"));
    QCOMPARE(j["fy"].toDouble(), 0.5);
    QCOMPARE(j["ay_ratio"].toDouble(), 0.9);
    QCOMPARE(j["theta"].toDouble(), 20.0);
    QCOMPARE(j["normalization"].toString(), QString("product"));
    // RSN68 UP peaks at 0.1643 g (resources/records/SOURCES.md: NPTS 7945, DT 0.01 s).
    QCOMPARE_LT(std::abs(j["vertical"].toObject()["peak_g"].toDouble() - 0.1643), 1e-3);
    const QJsonArray outcome = j["outcome"].toArray();
    QCOMPARE(outcome.size(), 2);
    // 1.1 g at 1 Hz collapses even the 1-DOF slab (A_crit 0.98): the planar one must too.
    QCOMPARE(outcome[1].toArray()[0].toString(), QString("collapsed"));
    const QJsonArray sides = j["exit_side"].toArray();
    QVERIFY(sides[1].toArray()[0].toString() == "across" ||
            sides[1].toArray()[0].toString() == "along");
    QVERIFY(sides[0].toArray()[0].isNull()); // 0.6 g at 1 Hz with f_y 0.5 Hz: no collapse
}

void TestCliPlanar::badInputExitsTwo_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("flag");
    const QStringList base{"simulate", "--model", "planar", "--amplitude", "1", "--frequency", "1"};
    QTest::newRow("missing fy") << base << "--fy";
    QTest::newRow("negative fy") << base + QStringList{"--fy", "-1"} << "--fy";
    QTest::newRow("NaN ay ratio") << base + QStringList{"--fy", "1", "--ay-ratio", "nan"}
                                  << "--ay-ratio";
    QTest::newRow("zero theta") << base + QStringList{"--fy", "1", "--theta", "0"} << "--theta";
    QTest::newRow("unknown normalization")
        << base + QStringList{"--fy", "1", "--normalization", "peak"} << "--normalization";
    QTest::newRow("missing vertical file")
        << base + QStringList{"--fy", "1", "--vertical", "/no/such/file.AT2"} << "--vertical";
    QTest::newRow("paper solver") << base + QStringList{"--fy", "1", "--solver", "paper"}
                                  << "--solver";
    QTest::newRow("planar flag on slab1d")
        << QStringList{"simulate", "--amplitude", "1", "--frequency", "1", "--fy", "1"} << "--fy";
}

void TestCliPlanar::badInputExitsTwo() {
    QFETCH(QStringList, args);
    QFETCH(QString, flag);
    const Run r = cli(args);
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(flag.toUtf8()), r.err.constData());
}

QTEST_APPLESS_MAIN(TestCliPlanar)
#include "tst_cli_planar.moc"
