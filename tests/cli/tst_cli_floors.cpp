// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli floors as a user runs it: the paper's building (16 levels, 177 ft, T = 1 s) under
// the Pacoima Dam 164 record (NGA RSN77).
//  - the JSON keys of issue 19; 16 modes, the first at T, participation summing the roof to 1
//    (sum_r Gamma_r phi_r,roof = 1 with phi_roof = 1);
//  - the roof demands equal the hand values of tests/core/tst_floors_demand.cpp (ASCE 7-22
//    0.70421 g, EN 1998-1 rigid 0.71875 g);
//  - per level, critical PGA = critical floor peak x PGA / PFA (the building is linear);
//  - the example project with its "floors" settings; the history CSV under a German locale;
//  - bad input: exit 2 with the flag and the value named;
//  - the report of the example project has the floor-motion section (read with pdftotext),
//    the report of the plain paper project has none.

#include "CliRun.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcessEnvironment>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

namespace {

const QString kRoot = KINSTAB_SOURCE_DIR;
const QString kPaper = kRoot + "/resources/examples/paper-16-story.json";
const QString kFloors = kRoot + "/resources/examples/paper-16-story-floors.json";
const QString kPacoima = kRoot + "/resources/records/RSN77_SFERN_PUL164.AT2";

QJsonObject json(const Run& r) {
    return QJsonDocument::fromJson(r.out).object();
}

} // namespace

class TestCliFloors : public QObject {
    Q_OBJECT
private slots:
    void paperBuildingUnderPacoima();
    void exampleProjectAndHistoryCsv();
    void badInput_data();
    void badInput();
    void reportHasTheSection();
    void tinyBuildingPeriodIsNamed();
};

void TestCliFloors::paperBuildingUnderPacoima() {
    const Run r = cli({"floors", "--project", kPaper, "--record", kPacoima});
    QCOMPARE(r.code, 0);
    const QJsonObject j = json(r);
    const QJsonArray modes = j["modes"].toArray(), levels = j["levels"].toArray();
    QCOMPARE(modes.size(), 16);
    QCOMPARE_LT(std::abs(modes[0].toObject()["period_s"].toDouble() - 1.0), 1e-12);
    double roof = 0;
    for (const auto& m : modes)
        roof += m.toObject()["participation"].toDouble();
    QCOMPARE_LT(std::abs(roof - 1.0), 1e-9);
    QCOMPARE_LT(std::abs(j["asce7_22_ta_s"].toDouble() - 0.97053), 5e-5);
    QCOMPARE(levels.size(), 16);
    const double pga = j["pga_g"].toDouble();
    QVERIFY(pga > 1.0); // the Pacoima Dam record's PGA exceeds 1 g
    for (int i = 0; i < 16; ++i) {
        const QJsonObject l = levels[i].toObject();
        QCOMPARE(l["level"].toInt(), i + 1);
        QCOMPARE_LT(std::abs(l["height"].toDouble() - 177.0 * (i + 1) / 16.0), 1e-9);
        QCOMPARE(l["weight"].toDouble(), 1.0);
        const double pfa = l["pfa_g"].toDouble();
        QCOMPARE_LT(std::abs(l["pfa_over_pga"].toDouble() - pfa / pga), 1e-12);
        QVERIFY(l["asce7_22_hf"].isDouble() && l["ec8_pfa_g"].isDouble());
        QVERIFY(l["critical_pga_g"].isDouble());
        const double expect = l["critical_floor_peak_g"].toDouble() * pga / pfa;
        QCOMPARE_LT(std::abs(l["critical_pga_g"].toDouble() - expect), 1e-9 * expect);
    }
    const QJsonObject top = levels[15].toObject();
    QCOMPARE_LT(std::abs(top["asce7_22_pfa_g"].toDouble() - 0.70421), 5e-5);
    QCOMPARE_LT(std::abs(top["ec8_pfa_g"].toDouble() - 0.71875), 1e-12);
    QCOMPARE(j["slab_level"].toInt(), 16);
    QCOMPARE(j["checks"].toArray().size(), 3);
    QVERIFY(j["sdof_roof"].toObject()["pfa_g"].toDouble() > 0);
    // The floor checks of the assessment: the code formula's roof demand 0.70421 g against the
    // roof's critical floor peak, and 0.4 S_DS = 0.4 g (S_DS = 1.0) against the critical PGA.
    const QJsonObject asce = j["checks"].toArray()[0].toObject();
    QCOMPARE(asce["id"].toString(), QString("floors.asce7_22.design"));
    const QJsonArray cmp = asce["comparisons"].toArray();
    QCOMPARE_LT(std::abs(cmp[0].toObject()["demand"].toDouble() - 0.4), 1e-12);
    QCOMPARE(cmp[0].toObject()["capacity"].toDouble(), top["critical_pga_g"].toDouble());
    QCOMPARE_LT(std::abs(cmp[1].toObject()["demand"].toDouble() - 0.70421), 5e-5);
    QCOMPARE(cmp[1].toObject()["capacity"].toDouble(), top["critical_floor_peak_g"].toDouble());
}

void TestCliFloors::exampleProjectAndHistoryCsv() {
    QTemporaryDir dir;
    const QString csv = dir.filePath("floors.csv");
    QProcess p;
    auto env = QProcessEnvironment::systemEnvironment();
    env.insert("LC_ALL", "de_DE.UTF-8");
    p.setProcessEnvironment(env);
    p.start(KINSTAB_CLI, {"floors", "--project", kFloors, "--slab-level", "8", "--stiffness",
                          "weight", "--no-critical", "--history-csv", csv});
    QVERIFY(p.waitForFinished(120000));
    QCOMPARE(p.exitCode(), 0);
    const QJsonObject j = QJsonDocument::fromJson(p.readAllStandardOutput()).object();
    QCOMPARE(j["slab_level"].toInt(), 8);
    QCOMPARE(j["stiffness"].toString(), QString("weight"));
    QCOMPARE(j["damping"].toDouble(), 0.05);
    QVERIFY(j["levels"].toArray()[7].toObject()["critical_pga_g"].isNull()); // --no-critical
    QVERIFY(j["checks"].toArray().isEmpty());
    QFile f(csv);
    QVERIFY(f.open(QIODevice::ReadOnly));
    const QList<QByteArray> lines = f.readAll().split('\n');
    QVERIFY(lines[0].startsWith("t_s,ground_g,level_1_g,"));
    QVERIFY(lines[0].endsWith(",level_16_g,sdof_roof_g"));
    QCOMPARE(lines[1].split(',').size(), 19);
    QVERIFY(lines[2].startsWith("0.01,")); // C-locale decimal point under de_DE
}

void TestCliFloors::badInput_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("message");
    QTest::newRow("no project") << QStringList{"floors"} << "--project";
    QTest::newRow("no record") << QStringList{"floors", "--project", kPaper} << "--record: missing";
    QTest::newRow("stiffness") << QStringList{"floors", "--project", kFloors, "--stiffness", "soft"}
                               << "--stiffness";
    QTest::newRow("damping") << QStringList{"floors", "--project", kFloors, "--damping", "1.5"}
                             << "--damping 1.5";
    QTest::newRow("slab level") << QStringList{"floors", "--project", kFloors, "--slab-level", "17"}
                                << "--slab-level 17";
    QTest::newRow("record file") << QStringList{"floors", "--project", kPaper, "--record",
                                                "/nonexistent.at2"}
                                 << "--record /nonexistent.at2";
}

void TestCliFloors::badInput() {
    QFETCH(QStringList, args);
    QFETCH(QString, message);
    const Run r = cli(args);
    QCOMPARE(r.code, 2);
    QVERIFY2(QString(r.err).contains(message), r.err.constData());
}

void TestCliFloors::reportHasTheSection() {
    QVERIFY2(run("pdftotext", {"-v"}).code == 0, "pdftotext missing: apt install poppler-utils");
    QTemporaryDir dir;
    const QString pdf = dir.filePath("floors.pdf"), plain = dir.filePath("plain.pdf");
    QCOMPARE(cli({"report", "--project", kFloors, "-o", pdf, "--figure-grid", "5"}).code, 0);
    const QString text = run("pdftotext", {"-layout", pdf, "-"}).out;
    QVERIFY(text.contains("Floor motions and today"));
    QVERIFY(text.contains("Floor checks at the slab's level"));
    QVERIFY(text.contains("ASCE/SEI 7-22 §13.3.1, MCE_R level"));
    QVERIFY(text.contains("0.704")); // ASCE design PFA at the roof (tst_floors_demand)
    QCOMPARE(cli({"report", "--project", kPaper, "-o", plain, "--figure-grid", "5"}).code, 0);
    QVERIFY(!QString(run("pdftotext", {"-layout", plain, "-"}).out).contains("Floor motions"));
}

// Issue 31: building.period_s = 1e-300 said "floor period -nan s"; the floor motions filter the
// record at the building's period, whose least is the floor filter's (0.01 s).
void TestCliFloors::tinyBuildingPeriodIsNamed() {
    QFile f(kFloors);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QByteArray text = f.readAll();
    const qsizetype at = text.indexOf("\"period_s\": ") + 12; // the building's, the first
    text.replace(at, text.indexOf(',', at) - at, " 1e-300");
    text.replace("../records/", (kRoot + "/resources/records/").toUtf8());
    QTemporaryDir dir;
    QFile out(dir.filePath("p.json"));
    QVERIFY(out.open(QIODevice::WriteOnly));
    out.write(text);
    out.close();
    const Run r = cli({"floors", "--project", dir.filePath("p.json"), "--record", kPacoima});
    QCOMPARE(r.code, 2);
    // The building's period range (core/codes/Building.h, kMinPeriodS) refuses it first.
    QVERIFY2(r.err.contains("building.period_s = 1e-300 s: must be between 0.02 and 20"),
             r.err.constData());
}

QTEST_APPLESS_MAIN(TestCliFloors)
#include "tst_cli_floors.moc"
