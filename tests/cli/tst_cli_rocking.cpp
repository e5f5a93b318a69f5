// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli rocking and rocking-map (issue 32): the JSON contract on published cases (Makris &
// Roussos 2000's worked example, Zhang & Makris 2001's safe cape, Housner 1963's free rocking),
// sliding, the history, the map as JSON and CSV, and bad input refused with exit 2 naming the
// flag and the value.

#include "ExtremeInputs.h"

#include "core/rocking/Block.h"
#include "core/rocking/Pulse.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <numbers>
#include <random>

namespace {

constexpr double g = 9.80665;

QJsonObject json(const Run& r) {
    return QJsonDocument::fromJson(r.out).object();
}

QString num(double x) {
    return QString::number(x, 'g', 17);
}

// Zhang & Makris 2001's block: alpha 0.25, p 2.14 rad/s, so R = 3g / (4 p^2).
QStringList zhangMakrisBlock() {
    const double r = 3.0 * g / (4.0 * 2.14 * 2.14);
    return {"--half-width", num(r * std::sin(0.25)), "--half-height", num(r * std::cos(0.25))};
}

struct FlagCase {
    const kinstab::NumberInput* input;
    QStringList command; // runs with the flag added
};

// Every numeric flag of rocking with a command it runs in (issue 31's extremes, as
// tst_cli_extremes does for the slab's flags).
QList<FlagCase> flagCases() {
    const QStringList block = {"rocking", "--half-width", "0.2", "--half-height", "0.6"};
    const QStringList pulse = {"--pulse", "one-sine",    "--pulse-frequency",
                               "2",       "--amplitude", "0.5"};
    return {{&kinstab::kHalfWidthInput,
             {"rocking", "--half-height", "0.6", "--pulse", "half-sine", "--pulse-frequency", "1",
              "--amplitude", "0.5"}},
            {&kinstab::kHalfHeightInput,
             {"rocking", "--half-width", "0.2", "--pulse", "half-sine", "--pulse-frequency", "1",
              "--amplitude", "0.5"}},
            {&kinstab::kRestitutionInput, block + pulse},
            {&kinstab::kBlockMuInput, block + pulse},
            {&kinstab::kInitialTiltInput, block + QStringList{"--restitution", "0.9"}},
            {&kinstab::kRockingDurationInput, block + pulse},
            {&kinstab::kPulseAmplitudeInput,
             block + QStringList{"--pulse", "half-sine", "--pulse-frequency", "1"}},
            {&kinstab::kPulseFrequencyInput,
             block + QStringList{"--pulse", "one-cosine", "--amplitude", "0.5"}},
            {&kinstab::kPulseDurationInput,
             block + QStringList{"--pulse", "rectangular", "--amplitude", "0.5"}}};
}

} // namespace

class TestCliRocking : public QObject {
    Q_OBJECT
    QTemporaryDir dir_;

private slots:
    void makrisRoussosExample() {
        // Makris & Roussos 2000: b 0.2 m, h 0.6 m, half-sine of omega_p = 2 pi, linearised:
        // 5.430 m/s^2 survives, 5.440 m/s^2 overturns.
        const QStringList block = {
            "rocking",  "--half-width", "0.2",       "--half-height",     "0.6",
            "--linear", "--pulse",      "half-sine", "--pulse-frequency", "1"};
        Run r = cli(block + QStringList{"--amplitude", num(5.430 / g)});
        QCOMPARE(r.code, 0);
        QJsonObject j = json(r);
        QCOMPARE(j["outcome"].toString(), QString("rocks"));
        QVERIFY(j["overturn_time_s"].isNull());
        QVERIFY(j["max_theta_over_alpha"].toDouble() > 0.5 &&
                j["max_theta_over_alpha"].toDouble() < 1.0);
        QVERIFY(j["impact_times_s"].toArray().size() > 0);
        QCOMPARE(j["sliding_displacement_m"].toDouble(), 0.0);
        r = cli(block + QStringList{"--amplitude", num(5.440 / g)});
        QCOMPARE(r.code, 0);
        j = json(r);
        QCOMPARE(j["outcome"].toString(), QString("overturns"));
        QVERIFY(j["overturn_time_s"].toDouble() > 0.5);
        QVERIFY(j["impact_times_s"].toArray().isEmpty());
        QVERIFY(j.contains("kinstab_version"));
    }
    void zhangMakrisCritical() {
        // Zhang & Makris 2001 (eta 0.9, omega_p / p = 5, linearised one-sine): overturning from
        // 3.02 alpha g to 6.32, then again from eq. 47's 7.168 (tst_rocking_pulses): in g,
        // alpha = 0.25.
        const Run r =
            cli(QStringList{"rocking"} + zhangMakrisBlock() +
                QStringList{"--linear", "--restitution", "0.9", "--pulse", "one-sine",
                            "--pulse-frequency", num(5.0 * 2.14 / (2 * std::numbers::pi)),
                            "--amplitude", "0.5", "--critical", "--max-amplitude", "2.5"});
        QCOMPARE(r.code, 0);
        const QJsonObject j = json(r);
        const QJsonArray iv = j["overturning_intervals_g"].toArray();
        QCOMPARE(iv.size(), 2);
        QCOMPARE_LT(std::abs(j["critical_amplitude_g"].toDouble() - 3.0186 * 0.25), 1e-3);
        QCOMPARE_LT(std::abs(iv[0].toArray()[1].toDouble() - 6.3181 * 0.25), 1e-3);
        QCOMPARE_LT(std::abs(iv[1].toArray()[0].toDouble() - 7.1681 * 0.25), 1e-3);
        QCOMPARE(iv[1].toArray()[1].toDouble(), 2.5);
        QCOMPARE(j["outcome"].toString(), QString("rocks")); // 2 alpha g: below the first interval
    }
    void thinStandingGapsFound() {
        // Zhang & Makris 2001's block (alpha 0.25, p 2.14 rad/s), linearised, eta 0.9, one-cosine
        // pulse of omega_p / p = 1.5, amplitudes up to 5 g: overturning from 1.172 alpha g with
        // two standing gaps about 0.01 alpha g wide (1.2246-1.2341 and 1.2837-1.2979 alpha g) and
        // the safe cape from 2.993 to 3.300 alpha g. The reference is a brute-force scan of
        // 20,000 amplitudes (a step of 1e-3 alpha g, a tenth of the gaps), each change bisected;
        // the default 200-point scan (step 0.1 alpha g) without refinement misses both gaps.
        const QStringList run = QStringList{"rocking"} + zhangMakrisBlock() +
                                QStringList{"--linear",
                                            "--restitution",
                                            "0.9",
                                            "--pulse",
                                            "one-cosine",
                                            "--pulse-frequency",
                                            num(1.5 * 2.14 / (2 * std::numbers::pi)),
                                            "--amplitude",
                                            "0.5",
                                            "--critical"};
        const Run fine = cli(run + QStringList{"--scan-points", "20000", "--refine-depth", "0",
                                               "--max-runs", "100000"});
        const Run coarse = cli(run + QStringList{"--refine-depth", "0"});
        const Run refined = cli(run);
        QCOMPARE(fine.code, 0);
        QCOMPARE(coarse.code, 0);
        QCOMPARE(refined.code, 0);
        const QJsonArray want = json(fine)["overturning_intervals_g"].toArray();
        QCOMPARE(want.size(), 4);
        QCOMPARE(json(fine)["critical_run_limit_reached"].toBool(), false);
        QCOMPARE(json(coarse)["overturning_intervals_g"].toArray().size(), 2);
        const QJsonObject j = json(refined);
        const QJsonArray got = j["overturning_intervals_g"].toArray();
        QCOMPARE(got.size(), want.size());
        double previous = 0.0;
        for (int i = 0; i < got.size(); ++i) {
            const double from = got[i].toArray()[0].toDouble();
            const double to = got[i].toArray()[1].toDouble();
            QVERIFY(previous < from && from < to); // increasing, disjoint, each non-empty
            previous = to;
            // Both bisected to 1e-4 relative: the ends agree to twice that.
            QCOMPARE_LE(std::abs(from - want[i].toArray()[0].toDouble()), 2e-4 * from);
            QCOMPARE_LE(std::abs(to - want[i].toArray()[1].toDouble()), 2e-4 * to);
        }
        QCOMPARE(got.last().toArray()[1].toDouble(), 5.0); // open to the maximum
        QCOMPARE(j["critical_amplitude_g"].toDouble(), got[0].toArray()[0].toDouble());
        QCOMPARE_LE(std::abs(j["critical_amplitude_g"].toDouble() / 0.25 - 1.1721), 1e-3);
        QCOMPARE(j["critical_run_limit_reached"].toBool(), false);
        QVERIFY(j["critical_runs"].toInt() < 1000); // against about 20,000 for the brute force
    }
    void runLimitIsSaid() {
        const Run r = cli(QStringList{"rocking"} + zhangMakrisBlock() +
                          QStringList{"--linear", "--restitution", "0.9", "--pulse", "one-cosine",
                                      "--pulse-frequency", num(1.5 * 2.14 / (2 * std::numbers::pi)),
                                      "--amplitude", "0.5", "--critical", "--max-runs", "210"});
        QCOMPARE(r.code, 0);
        const QJsonObject j = json(r);
        QCOMPARE(j["critical_run_limit_reached"].toBool(), true);
        QCOMPARE(j["critical_runs"].toInt(), 210);
        QVERIFY(r.err.contains("--max-runs"));
        const QJsonArray iv = j["overturning_intervals_g"].toArray();
        QVERIFY(!iv.isEmpty());
        for (int i = 1; i < iv.size(); ++i)
            QVERIFY(iv[i - 1].toArray()[1].toDouble() < iv[i].toArray()[0].toDouble());
    }
    void nothingOverturnsGivesNull() {
        const Run r = cli({"rocking", "--half-width", "0.2", "--half-height", "0.6", "--pulse",
                           "half-sine", "--pulse-frequency", "20", "--amplitude", "0.2",
                           "--critical", "--max-amplitude", "0.3"});
        QCOMPARE(r.code, 0);
        const QJsonObject j = json(r);
        QVERIFY(j["critical_amplitude_g"].isNull());
        QVERIFY(j["overturning_intervals_g"].toArray().isEmpty());
        QCOMPARE(j["outcome"].toString(), QString("rest")); // 0.2 g < g tan alpha = 0.333 g
    }
    void freeRocking() {
        // Housner 1963: from rest at theta0 = alpha / 2 the first impact comes after
        // (1/p) acosh(2), p = sqrt(3 g / (4 R)), R = sqrt(0.4) m.
        const Run r = cli({"rocking", "--half-width", "0.2", "--half-height", "0.6", "--linear",
                           "--initial-tilt", "0.5", "--restitution", "0.9"});
        QCOMPARE(r.code, 0);
        const QJsonObject j = json(r);
        const double p = std::sqrt(3.0 * g / (4.0 * std::sqrt(0.4)));
        QCOMPARE_LT(std::abs(j["impact_times_s"].toArray()[0].toDouble() - std::acosh(2.0) / p),
                    1e-9);
        QCOMPARE(j["outcome"].toString(), QString("rocks"));
        QCOMPARE(j["max_theta_over_alpha"].toDouble(), 0.5);
    }
    void slidingAndHistory() {
        const QString history = dir_.filePath("h.csv");
        const Run r = cli({"rocking", "--half-width", "0.5", "--half-height", "0.5", "--mu", "0.3",
                           "--pulse", "one-sine", "--pulse-frequency", "2", "--amplitude", "0.6",
                           "--history", history, "--history-step", "0.05"});
        QCOMPARE(r.code, 0);
        const QJsonObject j = json(r);
        QCOMPARE(j["outcome"].toString(), QString("slides"));
        QCOMPARE_GT(std::abs(j["sliding_displacement_m"].toDouble()), 1e-3);
        QFile f(history);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QList<QByteArray> lines = f.readAll().split('\n');
        QCOMPARE(lines.front(),
                 QByteArray("t_s,theta_rad,theta_over_alpha,omega_rad_s,sliding_m,mode,a_h_g"));
        QVERIFY(lines.size() > 10);
        bool slid = false;
        for (const QByteArray& l : lines)
            slid = slid || l.contains(",slide,");
        QVERIFY(slid);
    }
    void badInput_data() {
        QTest::addColumn<QStringList>("extra");
        QTest::addColumn<QString>("named");
        const QStringList pulse = {"--pulse", "half-sine",   "--pulse-frequency",
                                   "1",       "--amplitude", "0.5"};
        QTest::newRow("half-width")
            << (QStringList{"--half-width", "-1", "--half-height", "0.6"} + pulse)
            << "--half-width -1";
        QTest::newRow("half-height")
            << (QStringList{"--half-width", "0.2", "--half-height", "200"} + pulse)
            << "--half-height 200";
        const QStringList block = {"--half-width", "0.2", "--half-height", "0.6"};
        QTest::newRow("restitution 0")
            << (block + QStringList{"--restitution", "0"} + pulse) << "--restitution 0";
        QTest::newRow("restitution 1.2")
            << (block + QStringList{"--restitution", "1.2"} + pulse) << "--restitution 1.2";
        QTest::newRow("mu") << (block + QStringList{"--mu", "0"} + pulse) << "--mu 0";
        QTest::newRow("tilt") << (block + QStringList{"--initial-tilt", "1"}) << "--initial-tilt 1";
        QTest::newRow("amplitude")
            << (block +
                QStringList{"--pulse", "one-sine", "--pulse-frequency", "1", "--amplitude", "2000"})
            << "--amplitude 2000";
        QTest::newRow("frequency")
            << (block +
                QStringList{"--pulse", "one-sine", "--pulse-frequency", "0", "--amplitude", "1"})
            << "--pulse-frequency 0";
        QTest::newRow("shape") << (block + QStringList{"--pulse", "wave", "--pulse-frequency", "1",
                                                       "--amplitude", "1"})
                               << "--pulse 'wave'";
        QTest::newRow("rectangular")
            << (block + QStringList{"--pulse", "rectangular", "--amplitude", "1"})
            << "--pulse-duration";
        QTest::newRow("no excitation") << block << "--initial-tilt";
        QTest::newRow("critical free")
            << (block + QStringList{"--initial-tilt", "0.5", "--critical"}) << "--critical";
        QTest::newRow("max amplitude")
            << (block + pulse + QStringList{"--critical", "--max-amplitude", "-1"})
            << "--max-amplitude -1";
        QTest::newRow("refine depth")
            << (block + pulse + QStringList{"--critical", "--refine-depth", "21"})
            << "--refine-depth 21";
        QTest::newRow("max runs") << (block + pulse + QStringList{"--critical", "--max-runs", "9"})
                                  << "--max-runs 9";
        QTest::newRow("max runs without critical")
            << (block + pulse + QStringList{"--max-runs", "100"}) << "--max-runs 100";
        QTest::newRow("duration") << (block + pulse + QStringList{"--duration", "0"})
                                  << "--duration 0";
        QTest::newRow("missing record")
            << (block + QStringList{"--record", dir_.filePath("none.at2")}) << "--record";
    }
    void badInput() {
        QFETCH(QStringList, extra);
        QFETCH(QString, named);
        const Run r = cli(QStringList{"rocking"} + extra);
        QCOMPARE(r.code, 2);
        QVERIFY2(QString::fromUtf8(r.err).contains(named), r.err.constData());
    }
    void mapJsonAndCsv() {
        const QStringList map =
            QStringList{"rocking-map"} + zhangMakrisBlock() +
            QStringList{"--linear", "--restitution",      "0.9", "--pulse",
                        "one-sine", "--amplitudes",       "1,9", "--frequencies",
                        "5,5",      "--amplitude-points", "9",   "--frequency-points",
                        "1"};
        Run r = cli(map);
        QCOMPARE(r.code, 0);
        const QJsonObject j = json(r);
        QVERIFY(j["complete"].toBool());
        const QJsonArray row = j["state"].toArray()[0].toArray();
        QCOMPARE(row.size(), 9);
        // a_p / (alpha g) = 1..9 at omega_p/p = 5: overturning from 3.02 to 6.32 and from 7.17.
        const int expected[] = {0, 0, 0, 1, 1, 1, 0, 1, 1};
        for (int k = 0; k < 9; ++k)
            QCOMPARE(row[k].toInt(), expected[k]);
        r = cli(map + QStringList{"--format", "csv"});
        QCOMPARE(r.code, 0);
        const QList<QByteArray> lines = r.out.trimmed().split('\n');
        QCOMPARE(lines.size(), 10);
        QCOMPARE(lines[0],
                 QByteArray("omega_p_over_p,a_p_over_alpha_g,state,max_theta_over_alpha"));
        QVERIFY(lines[4].contains(",overturns,"));
        QVERIFY(lines[7].contains(",survives,"));
        r = cli(
            {"rocking-map", "--half-width", "0.2", "--half-height", "0.6", "--amplitudes", "0,2"});
        QCOMPARE(r.code, 2);
        QVERIFY(r.err.contains("--amplitudes 0,2"));
        r = cli({"rocking-map", "--half-width", "0.2", "--half-height", "0.6", "--mu", "0.5"});
        QCOMPARE(r.code, 2);
        QVERIFY(r.err.contains("--mu 0.5"));
    }
    void everyFlagAtItsExtremes_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<bool>("inRange");
        std::mt19937_64 rng(32);
        for (const FlagCase& c : flagCases()) {
            const QString flag = QString::fromStdString(kinstab::flagName(*c.input));
            for (double x : extremeValues(*c.input, rng, 4))
                QTest::newRow(qPrintable(flag + " " + num(x)))
                    << (c.command + QStringList{flag, num(x)}) << c.input->range.contains(x);
        }
    }
    void everyFlagAtItsExtremes() {
        QFETCH(QStringList, args);
        QFETCH(bool, inRange);
        verifyExtremeRun(args, inRange);
    }
    void help() {
        Run r = cli({"--help"});
        QVERIFY(r.out.contains("  rocking "));
        QVERIFY(r.out.contains("  rocking-map "));
        r = cli({"rocking", "--help"});
        QCOMPARE(r.code, 0);
        for (const char* f :
             {"--half-width", "--half-height", "--restitution", "--linear", "--mu",
              "--initial-tilt", "--duration", "--pulse", "--pulse-frequency", "--pulse-duration",
              "--amplitude", "--record", "--critical", "--max-amplitude"})
            QVERIFY2(r.out.contains(f), f);
    }
};

QTEST_MAIN(TestCliRocking)
#include "tst_cli_rocking.moc"
