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
            << QStringList{"--frequency 1e-4", "0.001 and 1000 Hz"};
        QTest::newRow("critical 1e-4 Hz") << QStringList{"critical", "--frequencies", "1e-4"}
                                          << QStringList{"--frequencies", "0.001 and 1000 Hz"};
        QTest::newRow("planar fy 1e-4 Hz")
            << QStringList{"simulate",    "--model", "planar",      "--fy", "1e-4",
                           "--amplitude", "1",       "--frequency", "1"}
            << QStringList{"--fy 1e-4", "0.001 and 1000 Hz"};
        QTest::newRow("tolerance below one ulp")
            << QStringList{"critical", "--frequencies", "1", "--tolerance", "1e-17"}
            << QStringList{"--tolerance 1e-17", "smallest is 4.440892098500626e-15 g"};
        QTest::newRow("scan of 1e12 points")
            << QStringList{"critical", "--frequencies", "1",    "--scan-step",
                           "1e-12",    "--tolerance",   "1e-13"}
            << QStringList{"--scan-step 1e-12", "smallest step"};
        // Issue 31: accepted before, each ran for minutes or hours, or came back as NaN (exit 3)
        // or as a wrong "never collapses". Each input's range is declared once in core
        // (core/slab/SlabInputs.h, core/excitation/Envelope.h, EnvelopedSine.h,
        // core/sweep/CriticalAmplitude.h) with the physical reason for its bounds.
        QTest::newRow("mu 1e-300")
            << QStringList{"critical", "--frequencies", "2", "--mu", "1e-300"}
            << QStringList{"--mu 1e-300", "between 0.01 and 10"};
        QTest::newRow("planar mu 1e-300")
            << QStringList{"critical", "--frequencies", "2",    "--mu", "1e-300",
                           "--model",  "planar",        "--fy", "1"}
            << QStringList{"--mu 1e-300", "friction coefficient"};
        QTest::newRow("alpha 1e-9")
            << QStringList{"critical", "--frequencies", "2", "--alpha", "1e-9", "--beta", "3"}
            << QStringList{"--alpha 1e-9", "envelope decay rate must be between 0.001"};
        QTest::newRow("tstar 1e-300")
            << QStringList{"simulate", "--amplitude", "1.2",   "--frequency",
                           "1",        "--tstar",     "1e-300"}
            << QStringList{"--tstar 1e-300", "between 0.001 and 100 s"};
        QTest::newRow("wall width 4.9e-324")
            << QStringList{"simulate", "--amplitude",     "1.2",     "--frequency",
                           "1",        "--wall-width-in", "4.9e-324"}
            << QStringList{"--wall-width-in 4.9e-324", "wall width must be between 0.01"};
        for (const char* flag : {"--theta", "--limit", "--tstar"})
            QTest::newRow(qPrintable(QString("planar %1 1e-5").arg(flag)))
                << QStringList{"simulate", "--model",     "planar", "--fy", "1",   "--amplitude",
                               "1.2",      "--frequency", "1",      flag,   "1e-5"}
                << QStringList{QString(flag) + " 1e-5", "must be between"};
        QTest::newRow("scan of 1e6 points")
            << QStringList{"critical", "--frequencies", "1",    "--max-amplitude",
                           "1000",     "--scan-step",   "0.001"}
            << QStringList{"--scan-step 0.001", "at most 100000 scan points"};
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
