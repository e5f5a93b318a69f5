// SPDX-License-Identifier: GPL-3.0-or-later
// The cancellation-free closed forms of core/excitation/DecaySineIntegrals (docs/theory.md §6.2
// "numerical hygiene", §4 row 12) against composite Gauss-Legendre quadrature of a(tau),
// over short and long spans and with beta close to alpha.

#include "StressHelpers.h"
#include "core/excitation/EnvelopedSine.h"

#include <QtTest>
#include <cmath>

using namespace kinstab;

class TestDecaySineIntegrals : public QObject {
    Q_OBJECT
private slots:
    void againstQuadrature_data() {
        QTest::addColumn<double>("relGap");
        QTest::addColumn<double>("t0");
        QTest::addColumn<double>("h");
        for (double gap : {1.0, 1e-8, 1e-14})
            for (double t0 : {0.0, 3.7, 41.0, 400.0})
                for (double h : {1e-9, 1e-4, 0.3, 2.0, 9.0}) {
                    const QByteArray n = "gap " + QByteArray::number(gap) + " t0 " +
                                         QByteArray::number(t0) + " h " + QByteArray::number(h);
                    QTest::newRow(n.constData()) << gap << t0 << h;
                }
    }
    void againstQuadrature() {
        QFETCH(double, relGap);
        QFETCH(double, t0);
        QFETCH(double, h);
        const double t1 = t0 + h;
        h = t1 - t0; // the span the closed forms see (t1 rounds)
        const EnvelopedSine a(Envelope{0.15, 0.15 * (1.0 + relGap), std::nullopt}, 1.0, 1.0, 0.099);
        // int_{t0}^{t1} a and int_{t0}^{t1} (t1 - s) a(s) ds by quadrature.
        const testing::Integrals want =
            testing::integrate([&](double s) { return a.accel(t0 + s); }, h, 200);
        // Scales: |a| <= 1 over the span, so |first| <= h and |second| <= h^2 / 2.
        QCOMPARE_LE(std::abs(a.velocityChange(t0, t1) - want.first), 1e-13 * h);
        QCOMPARE_LE(std::abs(a.displacementChange(t0, t1) - want.second), 1e-13 * h * h);
        double end = 0.0;
        const double dv = a.velocityChangeAndAccel(t0, t1, end);
        QCOMPARE(dv, a.velocityChange(t0, t1));
        QCOMPARE_LE(std::abs(end - a.accel(t1)), 1e-14);
        // Both integrals at once (one series on a short span) against the quadrature too.
        double dx = 0.0;
        QCOMPARE_LE(std::abs(a.velocityAndDisplacementChange(t0, t1, dx) - want.first), 1e-13 * h);
        QCOMPARE_LE(std::abs(dx - want.second), 1e-13 * h * h);
        // a, a' and a'' at t1 from the integral's exponentials (the stop search's Halley steps):
        // a and a' against accel() and accelSlope(), a'' against the central difference of
        // accelSlope() (step 1e-5: truncation ~1e-10 |a''''|, rounding ~1e-11 |a'|).
        AccelAt at;
        QCOMPARE(a.velocityChangeAndSlopes(t0, t1, at), a.velocityChange(t0, t1));
        QCOMPARE_LE(std::abs(at.a - a.accel(t1)), 1e-14);
        QCOMPARE_LE(std::abs(at.da - a.accelSlope(t1)), 1e-13);
        const double step = 1e-5;
        const double d2a = (a.accelSlope(t1 + step) - a.accelSlope(t1 - step)) / (2.0 * step);
        QCOMPARE_LE(std::abs(at.d2a - d2a), 1e-8);
    }
};

QTEST_APPLESS_MAIN(TestDecaySineIntegrals)
#include "tst_decay_sine_integrals.moc"
