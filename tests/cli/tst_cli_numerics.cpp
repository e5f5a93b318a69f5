// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli on inputs that once gave a silent NaN, a false collapse or a hang: each now gives
// correct finite numbers, or exit status 2 naming the flag and the limit, in bounded time.

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QtTest>

#include "CliRun.h"

namespace {
// A hang is a failure too: 60 s is far above any of these runs (each well under 5 s).
Run cliBounded(const QStringList& args) {
    return run(KINSTAB_CLI, args, 60000);
}
} // namespace

class TestCliNumerics : public QObject {
    Q_OBJECT
private slots:
    void longStableRunHasNoNull() {
        // Fast envelope, A 3 g, f 30 Hz, mu 0.05: slips until tau ~ 4170; before, a stick
        // event near tau 3720.6 had null tau and delta, and residual_delta and tau_end were null.
        const Run r = cliBounded({"simulate", "--amplitude", "3", "--frequency", "30", "--mu",
                                  "0.05", "--envelope", "fast", "--events"});
        QCOMPARE(r.code, 0);
        const QJsonObject j = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(j["outcome"].toString(), QString("stable"));
        QVERIFY(j["residual_delta"].isDouble());
        QVERIFY(j["tau_end"].isDouble() && j["tau_end"].toDouble() > 3720.6);
        const QJsonArray events = j["events"].toArray();
        QVERIFY(events.size() > 1000);
        for (const QJsonValue& e : events) {
            const QJsonObject o = e.toObject();
            QVERIFY(o["tau"].isDouble() && o["delta"].isDouble() && o["velocity"].isDouble());
        }
    }
    void noFalseCollapse() {
        // Fast envelope, f 6 Hz, mu 0.1, A 3.44 g: stable (the edge is at 4.6106 g); before, it
        // "collapsed" with tau_c null.
        const Run r = cliBounded({"simulate", "--amplitude", "3.44", "--frequency", "6",
                                  "--envelope", "fast", "--mu", "0.1"});
        QCOMPARE(r.code, 0);
        const QJsonObject j = QJsonDocument::fromJson(r.out).object();
        QCOMPARE(j["outcome"].toString(), QString("stable"));
        QVERIFY(j["residual_delta"].isDouble());
    }
    void criticalAtSixHertz() {
        // The true edge is between 4.610566 and 4.610586 g (two independent references, one in
        // 40-digit arithmetic); the search's tolerance is 1e-6 g. Before: 3.43098.
        const Run r =
            cliBounded({"critical", "--frequencies", "6", "--envelope", "fast", "--mu", "0.1"});
        QCOMPARE(r.code, 0);
        const double a = QJsonDocument::fromJson(r.out).object()["a_crit"].toArray()[0].toDouble();
        QVERIFY2(a > 4.610566 - 1e-6 && a < 4.610586 + 1e-6, QByteArray::number(a, 'g', 10));
    }
    void refusedQuickly_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QStringList>("mentions");
        // Before, each of these ran for ever.
        QTest::newRow("simulate 1e-4 Hz")
            << QStringList{"simulate", "--amplitude", "1", "--frequency", "1e-4"}
            << QStringList{"--frequency 1e-4", "0.001 Hz"};
        QTest::newRow("critical 1e-4 Hz") << QStringList{"critical", "--frequencies", "1e-4"}
                                          << QStringList{"--frequencies", "0.001 Hz"};
        QTest::newRow("planar fy 1e-4 Hz")
            << QStringList{"simulate",    "--model", "planar",      "--fy", "1e-4",
                           "--amplitude", "1",       "--frequency", "1"}
            << QStringList{"--fy 1e-4", "0.001 Hz"};
        QTest::newRow("tolerance below one ulp")
            << QStringList{"critical", "--frequencies", "1", "--tolerance", "1e-17"}
            << QStringList{"--tolerance 1e-17", "smallest is 4.44e-15"};
        QTest::newRow("scan of 1e12 points")
            << QStringList{"critical", "--frequencies", "1",    "--scan-step",
                           "1e-12",    "--tolerance",   "1e-13"}
            << QStringList{"--scan-step 1e-12", "smallest step"};
    }
    void refusedQuickly() {
        QFETCH(QStringList, args);
        QFETCH(QStringList, mentions);
        const Run r = cliBounded(args);
        QCOMPARE(r.code, 2);
        for (const QString& m : mentions)
            QVERIFY2(QString::fromUtf8(r.err).contains(m), r.err.constData());
        QVERIFY(r.out.isEmpty());
    }
};

QTEST_MAIN(TestCliNumerics)
#include "tst_cli_numerics.moc"
