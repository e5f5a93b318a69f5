// SPDX-License-Identifier: GPL-3.0-or-later
// Every numeric model flag at the extremes a user can type (issue 31): the ends of its declared
// range (core/base/NumberInput.h declarations), just outside them, 1e-300, the smallest
// subnormal 4.9e-324, 1e308, zero and -1, and values drawn from a seeded log-uniform law over
// the whole double range. Each run must end in seconds with exit 0 (an answer) or 2 (a refusal
// naming the flag): never a hang, a crash, exit 1 (a bug) or a NaN in the output.
#include "ExtremeInputs.h"

#include "core/excitation/Envelope.h"
#include "core/excitation/EnvelopedSine.h"
#include "core/slab/SlabInputs.h"
#include "core/sweep/CriticalAmplitude.h"

#include <QtTest>

#include <cmath>
#include <random>

using namespace kinstab;

namespace {

struct FlagCase {
    const NumberInput* input;
    QStringList command; // the rest of a command line that runs with the flag added
};

QString shown(double x) {
    return QString::number(x, 'g', 17);
}

const QStringList kSimulate{"simulate", "--amplitude", "0.9", "--frequency", "1"};
const QStringList kPlanar{"simulate", "--model",     "planar", "--fy",
                          "1",        "--amplitude", "0.9",    "--frequency"};
const QStringList kCritical{"critical", "--frequencies", "1"};

QList<FlagCase> flagCases() {
    return {{&kMuInput, kSimulate},
            {&kMuInput, kCritical},
            {&kLimitInput, kSimulate},
            {&kTstarInput, kSimulate},
            {&kTstarInput, kCritical},
            {&kWallWidthInput, kSimulate},
            {&kDurationInput, kSimulate},
            {&kPaperStepsInput, kSimulate + QStringList{"--solver", "paper"}},
            {&kAlphaInput, kSimulate + QStringList{"--beta", "10000"}},
            {&kBetaInput, kSimulate + QStringList{"--alpha", "0.001"}},
            {&kThetaInput, kPlanar + QStringList{"1"}},
            {&kLimitInput, kPlanar + QStringList{"1"}},
            {&kTstarInput, kPlanar + QStringList{"1"}},
            {&kAyRatioInput, kPlanar + QStringList{"1"}},
            {&kMaxAmplitudeInput, kCritical},
            {&kScanStepInput, kCritical},
            {&kToleranceInput, kCritical},
            {&kAmplitudeInput, {"simulate", "--frequency", "1"}},
            {&kFrequencyInput, {"simulate", "--amplitude", "0.9"}}};
}

} // namespace

class TestCliExtremes : public QObject {
    Q_OBJECT
private slots:
    void everyFlagAtItsExtremesEndsInSeconds_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<bool>("inRange");
        std::mt19937_64 rng(31);
        for (const FlagCase& c : flagCases()) {
            const QString flag = QString::fromStdString(flagName(*c.input));
            for (double x : extremeValues(*c.input, rng, 6))
                QTest::newRow(qPrintable(c.command.first() + " " + flag + " " + shown(x)))
                    << (c.command + QStringList{flag, shown(x)}) << c.input->range.contains(x);
        }
    }
    void everyFlagAtItsExtremesEndsInSeconds() {
        QFETCH(QStringList, args);
        QFETCH(bool, inRange);
        verifyExtremeRun(args, inRange);
    }
    // Inputs each in range whose product is the work (core/sweep/SearchWork.h): a search at
    // the fastest sine, under the slowest envelope, with the finest paper solver, over the
    // widest scan; one run of each model at the fastest sine under the slowest envelope.
    void searchesAndRunsAtTheirExtremesEndInSeconds_data() {
        QTest::addColumn<QStringList>("args");
        const QStringList slow{"--alpha", "0.001", "--beta", "10000"};
        QTest::newRow("critical 1000 Hz") << QStringList{"critical", "--frequencies", "1000"};
        QTest::newRow("critical 100 Hz, slow envelope")
            << QStringList{"critical", "--frequencies", "100"} + slow;
        QTest::newRow("critical, paper solver 1e6 steps") << QStringList{
            "critical", "--frequencies", "2", "--solver", "paper", "--paper-steps", "1000000"};
        QTest::newRow("critical, 1e5 scan points to 1000 g") << QStringList{
            "critical", "--frequencies", "2",   "--max-amplitude", "1000", "--scan-step",
            "0.01",     "--mu",          "0.01"};
        QTest::newRow("simulate 1000 Hz, slow envelope")
            << QStringList{"simulate", "--amplitude", "5", "--frequency", "1000"} + slow;
        QTest::newRow("planar 1000 Hz, slow envelope")
            << QStringList{"simulate",    "--model", "planar",      "--fy", "1",
                           "--amplitude", "5",       "--frequency", "1000"} +
                   slow;
        QTest::newRow("surface to 1000 Hz, slow envelope")
            << QStringList{"surface", "--amplitudes", "0.7:5:0.1", "--frequencies", "1:1000:10"} +
                   slow;
    }
    void searchesAndRunsAtTheirExtremesEndInSeconds() {
        QFETCH(QStringList, args);
        const TimedRun t = timedCli(args);
        const Run& r = t.r;
        QVERIFY2(t.answeredOrRefused(), t.exitText().constData());
        if (r.code == 2) QVERIFY2(r.err.contains("half-periods"), r.err.constData());
    }
};

QTEST_MAIN(TestCliExtremes)
#include "tst_cli_extremes.moc"
