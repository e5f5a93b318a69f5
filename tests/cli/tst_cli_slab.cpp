// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli simulate | surface | critical as a user runs them (docs/user-guide.md "The command
// line"): JSON keys, exit codes, and messages that name the bad flag.

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include "CliRun.h"

class TestCliSlab : public QObject {
    Q_OBJECT
private slots:
    void simulateKeys() {
        const Run r = cli({"simulate", "--amplitude", "1.0", "--frequency", "1"});
        QCOMPARE(r.code, 0);
        const QJsonObject j = QJsonDocument::fromJson(r.out).object();
        for (const char* key : {"outcome", "tau_c", "gamma_c", "slip_intervals", "max_abs_delta",
                                "residual_delta", "work", "wall_time_s"})
            QVERIFY2(j.contains(key), key);
        QCOMPARE(j["outcome"].toString(),
                 QString("collapsed")); // Furgerson 1980: A = 1.00 collapses
        QVERIFY(j["tau_c"].toDouble() > 0);
        QCOMPARE(j["gamma_c"].toDouble(), 37.89 / j["tau_c"].toDouble());
    }
    void simulateStableHasNullTauC() {
        const Run r = cli({"simulate", "--amplitude", "0.95", "--frequency", "1"});
        QCOMPARE(r.code, 0);
        const QJsonObject j = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(j["outcome"].toString(), QString("stable")); // Furgerson 1980: A = 0.95 stable
        QVERIFY(j["tau_c"].isNull());
        QCOMPARE(j["gamma_c"].toDouble(), 0.0);
    }
    void simulateHistory() {
        QTemporaryDir dir;
        const QString file = dir.filePath("h.csv");
        const Run r =
            cli({"simulate", "--amplitude", "1.0", "--frequency", "1", "--history", file});
        QCOMPARE(r.code, 0);
        QFile f(file);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = f.readAll().trimmed().split('\n');
        QCOMPARE(lines.first(), QByteArray("tau,accel_g,delta,velocity,state"));
        QVERIFY(lines.size() > 100);
        QCOMPARE(std::abs(lines.last().split(',')[2].toDouble()),
                 1.0); // ends at collapse, |delta| = 1
    }
    void surfaceJsonAndCsv() {
        const Run r = cli({"surface", "--amplitudes", "0.7:1.15:0.05", "--frequencies",
                           "0.5:1.125:0.125", "--envelope", "slow", "--threads", "2"});
        QCOMPARE(r.code, 0);
        const QJsonObject j = QJsonDocument::fromJson(r.out).object();
        for (const char* key :
             {"model", "solver", "envelope", "mu", "tstar", "tau_ref", "amplitudes", "frequencies",
              "tau_c", "gamma_c", "outcome", "wall_time_s"})
            QVERIFY2(j.contains(key), key);
        QCOMPARE(j["amplitudes"].toArray().size(), 10);
        QCOMPARE(j["frequencies"].toArray().size(), 6);
        QCOMPARE(j["tau_c"].toArray()[0].toArray().size(), 6);
        QCOMPARE(j["tau_ref"].toDouble(), 63.13); // Table 4, slow, tau_max
        QTemporaryDir dir;
        const QString file = dir.filePath("s.csv");
        const Run c = cli({"surface", "--amplitudes", "1,1.1", "--frequencies", "1", "--format",
                           "csv", "-o", file});
        QCOMPARE(c.code, 0);
        QFile f(file);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll().trimmed().split('\n').size(), 3);
    }
    void criticalKeys() {
        const Run r = cli({"critical", "--frequencies", "1"});
        QCOMPARE(r.code, 0);
        const QJsonObject j = QJsonDocument::fromJson(r.out).object();
        const double a = j["a_crit"].toArray()[0].toDouble();
        QVERIFY(a > 0.95 && a <= 1.0); // the paper's critical ratio at 1 Hz
        const Run none = cli({"critical", "--frequencies", "1", "--max-amplitude", "0.7"});
        QCOMPARE(none.code, 0);
        QVERIFY(QJsonDocument::fromJson(none.out).object()["a_crit"].toArray()[0].isNull());
    }
    void badInput_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("unknown flag")
            << QStringList{"simulate", "--amplitude", "1", "--frequency", "1", "--bogus", "2"}
            << "--bogus";
        QTest::newRow("NaN amplitude")
            << QStringList{"simulate", "--amplitude", "nan", "--frequency", "1"} << "--amplitude";
        QTest::newRow("negative amplitude")
            << QStringList{"simulate", "--amplitude", "-1", "--frequency", "1"} << "--amplitude";
        QTest::newRow("zero frequency")
            << QStringList{"simulate", "--amplitude", "1", "--frequency", "0"} << "--frequency";
        QTest::newRow("missing frequency")
            << QStringList{"simulate", "--amplitude", "1"} << "--frequency";
        QTest::newRow("negative mu")
            << QStringList{"simulate", "--amplitude", "1", "--frequency", "1", "--mu", "-0.1"}
            << "--mu";
        QTest::newRow("bad envelope")
            << QStringList{"simulate", "--amplitude", "1",    "--frequency",
                           "1",        "--envelope",  "quick"}
            << "--envelope";
        QTest::newRow("beta below alpha")
            << QStringList{"simulate", "--amplitude", "1",      "--frequency", "1",
                           "--alpha",  "0.5",         "--beta", "0.1"}
            << "beta";
        QTest::newRow("empty grid")
            << QStringList{"surface", "--amplitudes", "", "--frequencies", "1"} << "--amplitudes";
        QTest::newRow("bad list") << QStringList{"surface", "--amplitudes", "1,a", "--frequencies",
                                                 "1"}
                                  << "--amplitudes";
        QTest::newRow("bad solver")
            << QStringList{"surface", "--amplitudes", "1", "--frequencies", "1", "--solver", "rk45"}
            << "--solver";
        QTest::newRow("bad format")
            << QStringList{"surface", "--amplitudes", "1", "--frequencies", "1", "--format", "xml"}
            << "--format";
        QTest::newRow("negative threads")
            << QStringList{"surface", "--amplitudes", "1", "--frequencies", "1", "--threads", "-2"}
            << "--threads";
        QTest::newRow("unknown command") << QStringList{"simulat"} << "simulat";
    }
    void badInput() {
        QFETCH(QStringList, args);
        QFETCH(QString, mentions);
        const Run r = cli(args);
        QCOMPARE(r.code, 2);
        QVERIFY2(QString::fromUtf8(r.err).contains(mentions), r.err.constData());
        QVERIFY(r.out.isEmpty() || args.first() == "simulat");
    }
};

QTEST_MAIN(TestCliSlab)
#include "tst_cli_slab.moc"
