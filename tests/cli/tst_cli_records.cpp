// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli record and simulate --record (docs/user-guide.md "The command line"), run as a user
// would.

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

namespace {

const QString kRecords = KINSTAB_SOURCE_DIR "/resources/records/";

struct Run {
    int exitCode = -1;
    QJsonObject json;
    QString err;
};

Run runCli(const QStringList& args) {
    QProcess p;
    p.start(KINSTAB_CLI, args);
    p.waitForFinished(60000);
    Run r;
    r.exitCode = p.exitCode();
    r.json = QJsonDocument::fromJson(p.readAllStandardOutput()).object();
    r.err = QString::fromUtf8(p.readAllStandardError());
    return r;
}

} // namespace

class TestCliRecords : public QObject {
    Q_OBJECT
private slots:
    void recordSummary();
    void recordFloorSpectrumAtOneOverT();
    void simulateRecordCollapses();
    void simulateRecordScaledAndHistory();
    void badInput_data();
    void badInput();
};

// SOURCES.md §4: RSN68 PEL-UP, 7945 points at 0.01 s, peak 0.1643 g.
void TestCliRecords::recordSummary() {
    const Run r = runCli({"record", "--file", kRecords + "RSN68_SFERN_PEL-UP.AT2"});
    QCOMPARE(r.exitCode, 0);
    const QJsonObject rec = r.json["record"].toObject();
    QCOMPARE(rec["npts"].toInt(), 7945);
    QCOMPARE(rec["dt"].toDouble(), 0.01);
    QCOMPARE_LE(std::abs(rec["peak_g"].toDouble() - 0.1643), 5e-5);
    QCOMPARE(rec["file_units"].toString(), QString("g"));
    QCOMPARE(rec["component"].toString(), QString("UP"));
    QVERIFY(r.json["floor"].isNull());
    QCOMPARE(r.json["spectrum"]["peaks"].toArray().size(), 5);
    QCOMPARE(r.json["envelope"]["of"].toString(), QString("ground"));
}

// Paper Figs. 25-26: through a 1 Hz, 2 % oscillator the Pacoima Dam motion concentrates at 1 Hz.
void TestCliRecords::recordFloorSpectrumAtOneOverT() {
    const Run r = runCli({"record", "--file", kRecords + "RSN77_SFERN_PUL164.AT2", "--floor-period",
                          "1", "--damping", "0.02", "--peaks", "1"});
    QCOMPARE(r.exitCode, 0);
    const QJsonObject floor = r.json["floor"].toObject();
    const double df = floor["spectrum"]["df_hz"].toDouble();
    QCOMPARE_LE(std::abs(floor["spectrum"]["peaks"][0]["frequency_hz"].toDouble() - 1.0), df);
    QVERIFY(floor["energy_near_1_over_T"].toDouble() > 0.5);
    QCOMPARE(r.json["envelope"]["of"].toString(), QString("floor"));
    QVERIFY(r.json["envelope"]["beta"].toDouble() > r.json["envelope"]["alpha"].toDouble());
    // Issue 35: the record's metrics, Sa at the floor period (the building's) unless
    // --sa-period says otherwise (core/excitation/RecordMetrics, tested in tst_record_metrics).
    const QJsonObject m = r.json["metrics"].toObject();
    QCOMPARE(m["sa_period_s"].toDouble(), 1.0);
    QCOMPARE(m["sa_damping"].toDouble(), 0.05);
    QCOMPARE(m["baseline_correction"].toString(), QString("none"));
    QCOMPARE(m["pga_g"].toDouble(), 1.219037); // the largest sample (SOURCES.md: PGA 1.219 g)
    for (const char* key : {"pgv_m_s", "pgd_m", "arias_m_s", "d5_95_s", "mean_period_s", "sa_g"})
        QVERIFY2(m[key].toDouble() > 0, key);
    const Run at2 = runCli({"record", "--file", kRecords + "RSN77_SFERN_PUL164.AT2",
                            "--floor-period", "1", "--sa-period", "2"});
    QCOMPARE(at2.json["metrics"]["sa_period_s"].toDouble(), 2.0);
    QVERIFY(at2.json["metrics"]["sa_g"].toDouble() != m["sa_g"].toDouble());
    const Run none = runCli({"record", "--file", kRecords + "RSN77_SFERN_PUL164.AT2"});
    QVERIFY(none.json["metrics"]["sa_g"].isNull());
}

// Rinaldi 228 as recorded, mu 0.5: the independent small-step reference of
// tst_records_motion (step h/3200) collapses at tau = 27.91484 (resolution 1e-5).
void TestCliRecords::simulateRecordCollapses() {
    const Run r = runCli({"simulate", "--record", kRecords + "Rinaldi228.AT2", "--mu", "0.5"});
    QCOMPARE(r.exitCode, 0);
    QCOMPARE(r.json["outcome"].toString(), QString("collapsed"));
    QCOMPARE_LE(std::abs(r.json["tau_c"].toDouble() - 27.91484), 1e-4);
    QCOMPARE(r.json["solver"].toString(), QString("exact"));
    QVERIFY(r.json["gamma_c"].toDouble() > 0.0);
    QCOMPARE(r.json["record"]["npts"].toInt(), 1991);
}

void TestCliRecords::simulateRecordScaledAndHistory() {
    QTemporaryDir dir;
    const QString csv = dir.filePath("h.csv");
    const Run r =
        runCli({"simulate", "--record", kRecords + "RSN68_SFERN_PEL-UP.AT2", "--amplitude", "0.9",
                "--floor-period", "0.5", "--scale", "one", "--history", csv});
    QCOMPARE(r.exitCode, 0);
    QCOMPARE_LT(std::abs(r.json["amplitude"].toDouble() - 0.9), 1e-12);
    QCOMPARE(r.json["tau_ref"].toDouble(), 1.0);
    QCOMPARE(r.json["floor_filter"]["period_s"].toDouble(), 0.5);
    QFile f(csv);
    QVERIFY(f.open(QIODevice::ReadOnly));
    QVERIFY(f.readAll().count('\n') > 10);
}

void TestCliRecords::badInput_data() {
    QTest::addColumn<QStringList>("args");
    QTest::addColumn<QString>("message");
    const QString up = kRecords + "RSN68_SFERN_PEL-UP.AT2";
    QTest::newRow("missing file") << QStringList{"record", "--file", kRecords + "none.AT2"}
                                  << ":0: cannot open the file";
    QTest::newRow("values file without dt")
        << QStringList{"record", "--file", kRecords + "BM68elc.acc"}
        << "BM68elc.acc:1: expected 2 columns";
    QTest::newRow("unknown unit") << QStringList{"record", "--file", up, "--record-unit", "furlong"}
                                  << "--record-unit furlong";
    QTest::newRow("negative floor period")
        << QStringList{"record", "--file", up, "--floor-period", "-1"} << "--floor-period -1";
    // Issue 31: was exit 0 with NaN floor samples and a floor peak of 0.0.
    QTest::newRow("floor period 1e-300")
        << QStringList{"record", "--file", up, "--floor-period", "1e-300"}
        << "--floor-period 1e-300: floor period 1e-300 s: must be at least 0.01 s and at most "
           "1000 s";
    QTest::newRow("floor period below 0.01 s")
        << QStringList{"simulate", "--record", up, "--floor-period", "0.009"}
        << "--floor-period 0.009";
    QTest::newRow("damping 1") << QStringList{"record", "--file",    up, "--floor-period",
                                              "1",      "--damping", "1"}
                               << "--damping 1";
    QTest::newRow("damping without period")
        << QStringList{"simulate", "--record", up, "--damping", "0.05"}
        << "--damping 0.05: needs --floor-period";
    QTest::newRow("frequency with record")
        << QStringList{"simulate", "--record", up, "--frequency", "1"} << "--frequency 1";
    QTest::newRow("paper solver with record")
        << QStringList{"simulate", "--record", up, "--solver", "paper"} << "--solver paper";
    QTest::newRow("negative target peak")
        << QStringList{"simulate", "--record", up, "--amplitude", "-1"} << "--amplitude -1";
    QTest::newRow("record on surface")
        << QStringList{"surface", "--record", up, "--amplitudes", "1", "--frequencies", "1"}
        << "--record";
    QTest::newRow("record flag without record")
        << QStringList{"simulate", "--amplitude", "1", "--frequency", "1", "--record-dt", "0.01"}
        << "--record-dt 0.01: needs --record";
    QTest::newRow("sa period 0") << QStringList{"record", "--file", up, "--sa-period", "0"}
                                 << "--sa-period 0: floor period 0 s: must be at least 0.01 s";
    QTest::newRow("sa period text")
        << QStringList{"record", "--file", up, "--sa-period", "one"} << "--sa-period";
    QTest::newRow("unknown channel")
        << QStringList{"record", "--file", kRecords + "pacoima_dam.V2", "--record-channel", "VERT"}
        << "it has: 9 RAD, 10 UP, 11 TAN";
}

void TestCliRecords::badInput() {
    QFETCH(QStringList, args);
    QFETCH(QString, message);
    const Run r = runCli(args);
    QCOMPARE(r.exitCode, 2);
    QVERIFY2(r.err.contains(message), qPrintable(r.err));
}

QTEST_APPLESS_MAIN(TestCliRecords)
#include "tst_cli_records.moc"
