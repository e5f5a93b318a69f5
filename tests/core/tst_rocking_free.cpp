// SPDX-License-Identifier: GPL-3.0-or-later
// Free rocking of a block (core/rocking): Housner's closed forms for the linearised equations,
// the energy balance at impacts, energy conservation between them, and the exact equations
// approaching the linearised ones as the block gets slender.

#include "core/rocking/FreeRocking.h"
#include "core/rocking/RockingSolver.h"

#include <QtTest>
#include <cmath>
#include <vector>

using namespace kinstab;

namespace {

RockingModel freeBlock(double b, double h, double tilt, RockingEquations eq, double eta) {
    RockingModel m;
    m.block = {b, h};
    m.initialTilt = tilt;
    m.equations = eq;
    m.restitution = eta;
    return m;
}

} // namespace

class TestRockingFree : public QObject {
    Q_OBJECT
private slots:
    void housnerTimeToFirstImpact_data() {
        QTest::addColumn<double>("tilt");
        for (double r : {0.05, 0.3, 0.5, 0.9, 0.99})
            QTest::newRow(qPrintable(QString::number(r))) << r;
    }
    void housnerTimeToFirstImpact() {
        // Housner 1963 eq. 3 (linearised): released from rest at theta0 = r alpha, the block
        // reaches theta = 0 after (1/p) acosh(1 / (1 - r)).
        QFETCH(double, tilt);
        const RockingModel m = freeBlock(0.2, 0.6, tilt, RockingEquations::Linearised, 0.9);
        const RockingResult r = simulateRocking(m, NoMotion{});
        QVERIFY(!r.impactTimes.empty());
        const double expected = std::acosh(1.0 / (1.0 - tilt)) / blockFrequency(m.block);
        QCOMPARE_LT(std::abs(r.impactTimes.front() - expected), 1e-9 * expected);
        QCOMPARE(housnerQuarterPeriod(blockFrequency(m.block), tilt), expected);
        QCOMPARE(r.outcome, RockingOutcome::Rocks);
        QCOMPARE(r.maxThetaOverAlpha, tilt);
    }
    void amplitudeAfterImpacts() {
        // Energy balance (Housner 1963): the linearised energy is theta'^2/2 - p^2 (alpha -
        // |theta|)^2 / 2 and an impact multiplies theta'^2 by eta^2, so after n impacts the
        // amplitude r_n (of alpha) satisfies (1 - r_n)^2 = 1 - eta^(2n) (1 - (1 - r)^2). Each
        // excursion between impacts n and n + 1 lasts twice Housner's quarter period of r_n.
        const double r0 = 0.6, eta = 0.9;
        const RockingModel m = freeBlock(0.2, 0.6, r0, RockingEquations::Linearised, eta);
        const RockingResult r = simulateRocking(m, NoMotion{});
        const double p = blockFrequency(m.block);
        QVERIFY(r.impactTimes.size() > 20);
        for (int n = 1; n <= 20; ++n) {
            const double rn = linearAmplitudeAfterImpacts(r0, eta, n);
            const double span = r.impactTimes[static_cast<std::size_t>(n)] -
                                r.impactTimes[static_cast<std::size_t>(n - 1)];
            QVERIFY2(std::abs(span - 2.0 * housnerQuarterPeriod(p, rn)) < 1e-8 * span,
                     qPrintable(QString("impact %1: %2 vs %3")
                                    .arg(n)
                                    .arg(span, 0, 'g', 15)
                                    .arg(2.0 * housnerQuarterPeriod(p, rn), 0, 'g', 15)));
        }
        // eta = 1 keeps the amplitude: r_n = r.
        QCOMPARE(linearAmplitudeAfterImpacts(r0, 1.0, 7), r0);
    }
    void energyConservedBetweenImpacts_data() {
        QTest::addColumn<bool>("exact");
        QTest::newRow("exact") << true;
        QTest::newRow("linearised") << false;
    }
    void energyConservedBetweenImpacts() {
        // Free rocking conserves E = theta'^2/2 + V(theta) between impacts (V = p^2
        // cos(alpha z - theta), linearised -p^2 (alpha z - theta)^2/2); at an impact E drops so
        // that theta'^2 at theta = 0 is multiplied by eta^2.
        QFETCH(bool, exact);
        const RockingEquations eq = exact ? RockingEquations::Exact : RockingEquations::Linearised;
        RockingModel m = freeBlock(0.5, 1.0, 0.8, eq, 0.8);
        m.duration = 6.0;
        struct Sample {
            double t, theta, omega;
        };
        std::vector<Sample> s;
        RockingRunOptions o;
        o.sampleInterval = 0.005;
        o.recorder = [&](const RockingSample& x) { s.push_back({x.t, x.theta, x.omega}); };
        const RockingResult r = simulateRocking(m, NoMotion{}, o);
        QVERIFY(r.impactTimes.size() >= 4);
        const double p = blockFrequency(m.block), alpha = blockAlpha(m.block);
        const double scale = p * p * alpha * alpha;
        // Compare each sample with the first sample after the last impact before it.
        std::size_t impact = 0;
        double reference = rockingEnergy(eq, p, alpha, s.front().theta, s.front().omega);
        int compared = 0;
        for (const Sample& x : s) {
            while (impact < r.impactTimes.size() && x.t >= r.impactTimes[impact]) {
                ++impact;
                reference = std::numeric_limits<double>::quiet_NaN();
            }
            if (x.theta == 0.0) continue; // the impact's own samples, before and after
            const double e = rockingEnergy(eq, p, alpha, x.theta, x.omega);
            if (std::isnan(reference)) {
                reference = e;
                continue;
            }
            QVERIFY2(std::abs(e - reference) < 1e-9 * scale,
                     qPrintable(QString("t %1: %2 vs %3").arg(x.t).arg(e).arg(reference)));
            ++compared;
        }
        QVERIFY(compared > 500);
    }
    void freeFateFromEnergy() {
        // Linearised, alpha 0.25, p 2: at theta = 0 moving outwards the block reaches its corner's
        // vertical iff theta' > p alpha (E > 0); past the vertical moving outwards it never
        // returns; inwards past it with E < 0 it turns back and falls.
        const auto eq = RockingEquations::Linearised;
        QVERIFY(freeFate(eq, 2.0, 0.25, 0.9, 0.0, 0.5001).overturns);
        const FreeFate below = freeFate(eq, 2.0, 0.25, 0.9, 0.0, 0.4999);
        QVERIFY(!below.overturns);
        // amplitude alpha - sqrt(-2E)/p with E = 0.4999^2/2 - 2^2 0.25^2/2
        const double e = 0.5 * 0.4999 * 0.4999 - 0.5 * 4.0 * 0.0625;
        QCOMPARE_LT(std::abs(below.maxAbsTheta - (0.25 - std::sqrt(-2.0 * e) / 2.0)), 1e-15);
        QVERIFY(freeFate(eq, 2.0, 0.25, 0.9, 0.3, 0.01).overturns);
        QVERIFY(freeFate(eq, 2.0, 0.25, 0.9, 0.3, -0.01).overturns);
        // Inwards from 0.3 fast enough to pass the vertical (E > 0), then an impact with
        // eta = 0.9 leaves eta^2 (E + p^2 alpha^2 / 2) of the kinetic energy at theta = 0.
        const double w = -0.5; // E = 0.125 - 0.5 * 4 * 0.0025 = 0.12 > 0
        const double v0sq = 2.0 * (0.5 * w * w - 0.5 * 4.0 * 0.05 * 0.05 + 0.5 * 4.0 * 0.0625);
        const bool passes = 0.81 * v0sq > 4.0 * 0.0625; // beyond the other corner's vertical?
        QCOMPARE(freeFate(eq, 2.0, 0.25, 0.9, 0.3, w).overturns, passes);
    }
    void exactApproachesLinearisedForSlenderBlocks() {
        // The linearised equation is the exact one to first order in alpha: the time to the first
        // impact from theta0 = alpha / 2 differs by O(alpha^2), so a block ten times more slender
        // agrees about a hundred times better.
        double previous = 0.0;
        for (double b : {0.1, 0.01, 0.001}) {
            RockingModel exact = freeBlock(b, 1.0, 0.5, RockingEquations::Exact, 0.9);
            RockingModel linear = freeBlock(b, 1.0, 0.5, RockingEquations::Linearised, 0.9);
            exact.duration = linear.duration = 3.0;
            const double te = simulateRocking(exact, NoMotion{}).impactTimes.front();
            const double tl = simulateRocking(linear, NoMotion{}).impactTimes.front();
            const double rel = std::abs(te - tl) / tl;
            if (previous > 0.0) QVERIFY2(rel < previous / 50.0, qPrintable(QString::number(rel)));
            previous = rel;
        }
        QVERIFY(previous < 1e-6);
    }
};

QTEST_APPLESS_MAIN(TestRockingFree)
#include "tst_rocking_free.moc"
