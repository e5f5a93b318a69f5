// SPDX-License-Identifier: GPL-3.0-or-later
// The planar model's Taylor-series evaluation of two enveloped sines under one envelope
// (core/slab/SinePairSeries.h) against their closed forms (EnvelopedSine::accel, accelSlope:
// the independent evaluation, from exp, expm1 and sin) at 20,000 times over the whole motion, for
// the paper's envelopes, a fast pair (10 Hz and 0.3 Hz), and alpha ~ beta (where the envelope is
// a difference of nearly equal exponentials). Both forms round the phase omega tau, which
// carries an error of about omega tau 1.1e-16 rad: the difference is held to 8 such units (plus
// 1e-15 of the amplitude), not to a fixed figure. Also: the value at a time does not depend on
// which times were asked before (the patch grid is fixed).

#include "core/excitation/EnvelopedSine.h"
#include "core/slab/SinePairSeries.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <random>

using namespace kinstab;

class TestSinePairSeries : public QObject {
    Q_OBJECT
private slots:
    void matchesClosedForm_data() {
        QTest::addColumn<double>("alpha");
        QTest::addColumn<double>("beta");
        QTest::addColumn<double>("fx");
        QTest::addColumn<double>("fy");
        QTest::newRow("moderate, 2 and 1 Hz") << 0.15 << 0.40 << 2.0 << 1.0;
        QTest::newRow("severe, 0.5 and 1 Hz") << 0.10 << 0.50 << 0.5 << 1.0;
        QTest::newRow("fast pair") << 0.15 << 0.40 << 10.0 << 0.3;
        QTest::newRow("alpha ~ beta") << 0.2 << 0.2 * (1.0 + 1e-12) << 1.5 << 0.7;
        QTest::newRow("no decay") << 0.0 << 0.4 << 3.0 << 1.0;
    }
    void matchesClosedForm() {
        QFETCH(double, alpha);
        QFETCH(double, beta);
        QFETCH(double, fx);
        QFETCH(double, fy);
        const double tstar = 0.099;
        const Envelope env{alpha, beta, std::nullopt};
        const EnvelopedSine x(env, 1.0, fx, tstar), y(env, 0.9, fy, tstar);
        SinePairSeries series(x, y);
        std::mt19937_64 rng(7);
        std::uniform_real_distribution<double> tau(0.0, 200.0);
        double worstA = 0.0, worstS = 0.0;
        for (int i = 0; i < 20000; ++i) {
            const double t = i < 100 ? i * 1e-3 : tau(rng); // the start, where e(tau) ~ 0
            const auto a = series.accel(t), s = series.slope(t);
            // Units of the phase's rounding (amplitudes 1 and 0.9; slopes scaled by omega).
            const double ux = 1e-15 + x.omega() * t * 1.1e-16, uy = 1e-15 + y.omega() * t * 1.1e-16;
            worstA = std::max(
                {worstA, std::abs(a[0] - x.accel(t)) / ux, std::abs(a[1] - y.accel(t)) / uy});
            worstS = std::max({worstS, std::abs(s[0] - x.accelSlope(t)) / ((1.0 + x.omega()) * ux),
                               std::abs(s[1] - y.accelSlope(t)) / ((1.0 + y.omega()) * uy)});
        }
        qInfo("worst |a - closed form| %.2f units, slope %.2f units", worstA, worstS);
        QVERIFY(worstA < 8.0);
        QVERIFY(worstS < 8.0);
    }

    void independentOfHistory() {
        const Envelope env{0.15, 0.40, std::nullopt};
        const EnvelopedSine x(env, 1.0, 2.0, 0.099), y(env, 0.9, 1.0, 0.099);
        SinePairSeries forward(x, y), backward(x, y);
        std::vector<double> times;
        for (int i = 0; i < 2000; ++i)
            times.push_back(0.05 * i);
        std::vector<std::array<double, 2>> a;
        for (double t : times)
            a.push_back(forward.accel(t));
        for (int i = static_cast<int>(times.size()) - 1; i >= 0; --i) {
            const auto b = backward.accel(times[static_cast<std::size_t>(i)]);
            QCOMPARE(b[0], a[static_cast<std::size_t>(i)][0]);
            QCOMPARE(b[1], a[static_cast<std::size_t>(i)][1]);
        }
    }

    void outsideTheGridFallsBack() {
        const Envelope env{0.15, 0.40, std::nullopt};
        const EnvelopedSine x(env, 1.0, 2.0, 0.099), y(env, 0.9, 1.0, 0.099);
        SinePairSeries series(x, y);
        QCOMPARE(series.accel(-1.0)[0], x.accel(-1.0));
        QCOMPARE(series.accel(2e7)[1], y.accel(2e7));
    }
};

QTEST_APPLESS_MAIN(TestSinePairSeries)
#include "tst_sine_pair_series.moc"
