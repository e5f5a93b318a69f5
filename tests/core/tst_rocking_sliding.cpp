// SPDX-License-Identifier: GPL-3.0-or-later
// A free-standing block that slides (core/rocking): with rocking impossible it is the slab of
// kinstab's 1-DOF model, and the two solvers must agree; the initiation criteria of Shenton
// 1996 and the pivot friction of Zhang & Makris 2001 eq. 20 decide between sliding, rocking and
// slide-rock; a base that drops away faster than gravity lifts the block off.

#include "core/base/PhysicalConstants.h"
#include "core/excitation/EnvelopedSine.h"
#include "core/rocking/RockingMotions.h"
#include "core/rocking/RockingSolver.h"
#include "core/slab/ExactSolver.h"

#include <QtTest>
#include <cmath>
#include <numbers>

using namespace kinstab;

namespace {
constexpr double g = kStandardGravity;
}

class TestRockingSliding : public QObject {
    Q_OBJECT
private slots:
    void slidingEqualsTheSlab_data() {
        QTest::addColumn<double>("amplitude");
        QTest::addColumn<double>("frequency");
        QTest::addColumn<double>("mu");
        QTest::newRow("A 0.5 f 2 mu 0.3") << 0.5 << 2.0 << 0.3;
        QTest::newRow("A 0.9 f 1 mu 0.6") << 0.9 << 1.0 << 0.6;
        QTest::newRow("A 0.3 f 5 mu 0.1") << 0.3 << 5.0 << 0.1;
    }
    void slidingEqualsTheSlab() {
        // A block with b/h = 1 cannot rock while mu < tan alpha = 1 (the friction force mu N
        // never tips it) and the base stays below g b/h: it slides as the 1-DOF slab of
        // docs/theory.md §4 does, u'' = -g (a + mu sgn u'). The slab's exact solver (closed-form
        // slip integrals) in tau = t / t* with t* = 1 s gives delta in units of g t*^2, i.e.
        // u = g delta metres. Agreement to 1e-8 of the largest sliding (the slab solver is exact
        // to a few ulps; this one integrates the same slip with DOP853 at 1e-10).
        QFETCH(double, amplitude);
        QFETCH(double, frequency);
        QFETCH(double, mu);
        const Envelope env = Envelope::fromPreset(EnvelopePreset::Moderate);
        const EnvelopedSine sine(env, amplitude, frequency, 1.0);
        SlabParams params;
        params.mu = mu;
        params.limit = 1e6;
        const SlabResult slab = solveExact(sine, params);
        QCOMPARE(slab.outcome, Outcome::Stable);

        RockingModel m;
        m.block = {0.5, 0.5};
        m.mu = mu;
        const auto motion = envelopedSineMotion(env, amplitude, frequency);
        const RockingResult r = simulateRocking(m, *motion);
        QCOMPARE(r.outcome, RockingOutcome::Slides);
        QVERIFY(!r.rocked);
        const double scale = g * slab.maxAbsDelta;
        QVERIFY(scale > 1e-3);
        QVERIFY2(std::abs(r.maxSliding - scale) < 1e-8 * scale,
                 qPrintable(
                     QString("max %1 vs %2").arg(r.maxSliding, 0, 'g', 15).arg(scale, 0, 'g', 15)));
        QVERIFY2(std::abs(r.slidingDisplacement - g * slab.residualDelta) < 1e-8 * scale,
                 qPrintable(QString("residual %1 vs %2")
                                .arg(r.slidingDisplacement, 0, 'g', 15)
                                .arg(g * slab.residualDelta, 0, 'g', 15)));
    }
    void shentonInitiation() {
        // Shenton 1996 (Zhang & Makris 2001 eq. 8): from rest under a slowly rising pulse the
        // block slides first when mu < tan alpha and rocks first when mu > tan alpha.
        // A half-sine of 0.8 g and 0.2 Hz on a block with tan alpha = 0.5:
        Pulse pulse;
        pulse.shape = PulseShape::HalfSine;
        pulse.frequencyHz = 0.2;
        pulse.amplitude = 0.45;
        RockingModel m;
        m.block = {0.25, 0.5};
        m.mu = 0.4; // slides from 0.4 g; rocking would need 0.5 g, and sliding never tips it
        RockingResult r = simulateRocking(m, PulseMotion(pulse));
        QCOMPARE(r.outcome, RockingOutcome::Slides);
        QVERIFY(r.slidingDisplacement < 0.0); // the base moves towards +x, the block lags
        m.mu = 0.7;                           // rocks from 0.5 g
        pulse.amplitude = 0.52;
        r = simulateRocking(m, PulseMotion(pulse));
        QCOMPARE(r.outcome, RockingOutcome::Rocks);
        QCOMPARE(r.slidingDisplacement, 0.0);
        pulse.amplitude = 0.39; // below both: rest
        QCOMPARE(simulateRocking(m, PulseMotion(pulse)).outcome, RockingOutcome::Rest);
    }
    void pivotFrictionGivesSlideRock() {
        // Zhang & Makris 2001 eq. 20: rocking needs |F| <= mu N at the pivot. With mu just above
        // tan alpha the block lifts, and a base acceleration that keeps growing past mu g makes
        // the friction the pivot needs exceed mu N: it slide-rocks.
        RockingModel m;
        m.block = {0.25, 0.5};
        m.mu = 0.55;
        Pulse pulse;
        pulse.shape = PulseShape::HalfSine;
        pulse.frequencyHz = 2.0;
        pulse.amplitude = 1.2;
        const RockingResult r = simulateRocking(m, PulseMotion(pulse));
        QVERIFY(r.slideRocked);
        QVERIFY(r.outcome == RockingOutcome::SlideRock || r.outcome == RockingOutcome::Overturns);
        QVERIFY(r.maxSliding > 0.0);
        // Without friction given the base holds the corner: it only rocks.
        m.mu.reset();
        const RockingResult held = simulateRocking(m, PulseMotion(pulse));
        QVERIFY(!held.slideRocked && !held.slid);
        QCOMPARE(held.maxSliding, 0.0);
    }
    void ampleFrictionIsAHeldBase() {
        // With friction to spare (mu = 10, far above what the pivot needs while it rocks) the
        // block never slides: the run is the one of a base that holds it (mu absent), to the
        // bit. A block already falling over is the exception: near theta = pi/2 its normal force
        // vanishes and the corner slips (slide-rock), but it overturns all the same.
        RockingModel held;
        held.block = {0.2, 0.6};
        RockingModel rough = held;
        rough.mu = 10.0;
        Pulse pulse;
        pulse.shape = PulseShape::OneSine;
        pulse.frequencyHz = 1.5;
        for (double a : {0.35, 0.4, 0.45, 0.5, 0.8}) {
            pulse.amplitude = a;
            const RockingResult h = simulateRocking(held, PulseMotion(pulse));
            RockingModel withDuration = rough;
            // mu given: no energy shortcut after the motion, so give it time to fall or rest
            withDuration.duration = h.endTime + 10.0;
            const RockingResult r = simulateRocking(withDuration, PulseMotion(pulse));
            QCOMPARE(r.outcome, h.outcome);
            if (h.outcome == RockingOutcome::Overturns) continue;
            QVERIFY(!r.slid);
            QVERIFY(h.impactTimes.size() > 3);
            QCOMPARE(r.impactTimes.size(), h.impactTimes.size());
            for (std::size_t i = 0; i < h.impactTimes.size(); ++i)
                QCOMPARE(r.impactTimes[i], h.impactTimes[i]);
        }
    }
    void baseDroppingAwayLiftsTheBlock() {
        // With a vertical base acceleration below -g the base falls faster than the block: the
        // normal force vanishes and the run stops there (LeavesBase), at the instant 1 + a_v = 0.
        Accelerogram h, v;
        h.dt = v.dt = 0.01;
        h.samples.assign(201, 0.0);
        v.samples.assign(201, 0.0);
        for (std::size_t k = 0; k < 201; ++k)
            v.samples[k] = -2.0 * static_cast<double>(k) / 200.0;
        RockingModel m;
        m.block = {0.25, 0.5};
        const auto motion = recordMotion(h, std::nullopt, &v);
        const RockingResult r = simulateRocking(m, *motion);
        QCOMPARE(r.outcome, RockingOutcome::LeavesBase);
        QVERIFY(r.leavesBaseTime.has_value());
        QCOMPARE_LT(std::abs(*r.leavesBaseTime - 1.0), 1e-12); // a_v = -1 at t = 1 s
    }
    void limitsAreReported() {
        RockingModel m;
        m.block = {0.2, 0.6};
        m.initialTilt = 0.5;
        m.restitution = 1.0; // rocks for ever
        m.duration = 1e4;
        RockingRunOptions o;
        o.limits.maxEvents = 50;
        QVERIFY_THROWS_EXCEPTION(RockingLimitError, simulateRocking(m, NoMotion{}, o));
        o.limits.maxEvents = 100000;
        o.limits.maxSteps = 100;
        QVERIFY_THROWS_EXCEPTION(RockingLimitError, simulateRocking(m, NoMotion{}, o));
        // Without a duration, lossless free rocking stops after a bounded number of impacts.
        m.duration.reset();
        const RockingResult r = simulateRocking(m, NoMotion{});
        QCOMPARE(r.outcome, RockingOutcome::Rocks);
        QCOMPARE(r.impactTimes.size(), std::size_t(200));
    }
    void badModelIsRefused() {
        RockingModel m;
        m.block = {0.0, 0.6};
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, simulateRocking(m, NoMotion{}));
        m.block = {0.2, 0.6};
        m.restitution = 0.0;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, simulateRocking(m, NoMotion{}));
        m.restitution = 1.0;
        m.mu = -0.1;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, simulateRocking(m, NoMotion{}));
        m.mu.reset();
        m.initialTilt = 1.0;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, simulateRocking(m, NoMotion{}));
    }
    void housnerRestitutionByDefault() {
        // Housner 1963: eta = 1 - 1.5 sin^2 alpha (b 0.2, h 0.6: sin^2 alpha = 0.1).
        RockingModel m;
        m.block = {0.2, 0.6};
        QCOMPARE_LT(std::abs(restitutionOf(m) - 0.85), 1e-15);
        m.restitution = 0.7;
        QCOMPARE(restitutionOf(m), 0.7);
        QCOMPARE_LT(
            std::abs(blockFrequency({0.2, 0.6}) - std::sqrt(3.0 * g / (4.0 * std::sqrt(0.4)))),
            1e-15);
    }
};

QTEST_APPLESS_MAIN(TestRockingSliding)
#include "tst_rocking_sliding.moc"
