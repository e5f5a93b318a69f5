// SPDX-License-Identifier: GPL-3.0-or-later
// The products built on the block's runs (core/rocking): the overturning map on the thread pool
// (each point the single run it stands for; progress and cancel), the rocking spectrum, and a
// record as the base motion (a finely sampled pulse behaves as the pulse).

#include "core/rocking/OverturningMap.h"
#include "core/rocking/RockingMotions.h"
#include "core/rocking/RockingSolver.h"
#include "core/rocking/RockingSpectrum.h"

#include <QtTest>
#include <atomic>
#include <cmath>
#include <numbers>

using namespace kinstab;

namespace {

RockingModel zhangMakrisBlock() {
    RockingModel m;
    m.block = blockFromAlphaP(0.25, 2.14);
    m.restitution = 0.9;
    m.equations = RockingEquations::Linearised;
    return m;
}

// A pulse written out as a record at step dt (linear between samples).
Accelerogram sampled(const Pulse& p, double dt, double seconds) {
    const PulseMotion m(p);
    Accelerogram a;
    a.dt = dt;
    const auto n = static_cast<std::size_t>(std::lround(seconds / dt)) + 1;
    for (std::size_t k = 0; k < n; ++k)
        a.samples.push_back(m.horizontal(dt * static_cast<double>(k)));
    return a;
}

} // namespace

class TestRockingMap : public QObject {
    Q_OBJECT
private slots:
    void mapPointsAreSingleRuns() {
        const RockingModel m = zhangMakrisBlock();
        OverturningMapSpec s;
        s.shape = PulseShape::OneSine;
        s.amplitudeMin = 1.0;
        s.amplitudeMax = 9.0;
        s.frequencyMin = 2.0;
        s.frequencyMax = 6.0;
        s.amplitudePoints = 9;
        s.frequencyPoints = 5;
        s.threads = 2;
        std::atomic<std::size_t> last{0}, badTotals{0};
        SweepControl control;
        // Called on the worker threads: only atomics here, the checks after the map.
        control.onProgress = [&](std::size_t done, std::size_t total) {
            if (total != 45) ++badTotals;
            std::size_t seen = last.load();
            while (done > seen && !last.compare_exchange_weak(seen, done)) {
            }
        };
        const OverturningMap map = overturningMap(m, s, &control);
        QVERIFY(map.complete);
        QCOMPARE(last.load(), std::size_t(45));
        QCOMPARE(badTotals.load(), std::size_t(0));
        int over = 0, survive = 0;
        for (int i = 0; i < 5; ++i)
            for (int j = 0; j < 9; ++j) {
                Pulse p;
                p.shape = PulseShape::OneSine;
                p.amplitude = -map.amplitudes[static_cast<std::size_t>(j)] * 0.25;
                p.frequencyHz =
                    map.frequencies[static_cast<std::size_t>(i)] * 2.14 / (2.0 * std::numbers::pi);
                const RockingResult r = simulateRocking(m, PulseMotion(p));
                const bool o = r.outcome == RockingOutcome::Overturns;
                QCOMPARE(map.overturns[map.at(i, j)] == 1, o);
                (o ? over : survive) += 1;
                if (!o)
                    QCOMPARE(double(map.maxThetaOverAlpha[map.at(i, j)]),
                             double(float(r.maxThetaOverAlpha)));
            }
        QVERIFY(over > 0 && survive > 0);
        // omega_p/p = 5: 3.0 alpha g survives (below the first interval), 5.0 overturns and
        // 7.0 survives (the safe cape), 9.0 overturns (Zhang & Makris 2001; tst_rocking_pulses).
        QCOMPARE(int(map.overturns[map.at(3, 2)]), 0);
        QCOMPARE(int(map.overturns[map.at(3, 4)]), 1);
        QCOMPARE(int(map.overturns[map.at(3, 6)]), 0);
        QCOMPARE(int(map.overturns[map.at(3, 8)]), 1);
    }
    void mapCancels() {
        OverturningMapSpec s;
        s.amplitudePoints = s.frequencyPoints = 50;
        SweepControl control;
        control.cancel();
        const OverturningMap map = overturningMap(zhangMakrisBlock(), s, &control);
        QVERIFY(!map.complete);
    }
    void badMapIsRefused() {
        OverturningMapSpec s;
        s.amplitudeMin = 0.0;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, overturningMap(zhangMakrisBlock(), s));
        s = {};
        s.frequencyPoints = 0;
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, overturningMap(zhangMakrisBlock(), s));
    }
    void spectrumPointsAreSingleRuns() {
        // Makris & Konstantinidis 2003: blocks of one alpha, different p (size), one motion.
        Pulse p;
        p.shape = PulseShape::OneSine;
        p.frequencyHz = 1.0;
        p.amplitude = 0.4;
        const PulseMotion motion(p);
        RockingModel m;
        RockingSpectrumSpec s;
        s.alpha = 0.2;
        s.frequencies = {1.0, 1.5, 2.0, 3.0, 5.0};
        s.threads = 2;
        const std::vector<RockingSpectrumPoint> sp = rockingSpectrum(m, motion, s);
        QCOMPARE(sp.size(), std::size_t(5));
        bool someOverturn = false, someSurvive = false;
        for (const RockingSpectrumPoint& pt : sp) {
            RockingModel one;
            one.block = blockFromAlphaP(0.2, pt.p);
            QCOMPARE_LT(std::abs(blockFrequency(one.block) - pt.p), 1e-12 * pt.p);
            RockingRunOptions o;
            o.stopAtOverturnDecision = true;
            const RockingResult r = simulateRocking(one, motion, o);
            QCOMPARE(pt.overturns, r.outcome == RockingOutcome::Overturns);
            QCOMPARE(pt.maxThetaOverAlpha, r.maxThetaOverAlpha);
            (pt.overturns ? someOverturn : someSurvive) = true;
        }
        // Housner's scale effect: the large blocks (small p) survive what the small ones do not.
        QVERIFY(someOverturn && someSurvive);
        QVERIFY(!sp.front().overturns && sp.back().overturns);
    }
    void recordedPulseBehavesAsThePulse() {
        // The Makris & Roussos block under a half-sine of 0.5 g, 1 Hz (rocks, no overturning),
        // as the pulse and as a record sampled every 0.1 ms: the largest rotation agrees to the
        // interpolation error of the samples (O(dt^2) of the acceleration, ~1e-6 here).
        RockingModel m;
        m.block = {0.2, 0.6};
        m.equations = RockingEquations::Linearised;
        m.duration = 3.0;
        Pulse p;
        p.shape = PulseShape::HalfSine;
        p.frequencyHz = 1.0;
        p.amplitude = 0.5;
        const RockingResult pulse = simulateRocking(m, PulseMotion(p));
        const auto rec = recordMotion(sampled(p, 1e-4, 0.5));
        const RockingResult record = simulateRocking(m, *rec);
        QCOMPARE(pulse.outcome, RockingOutcome::Rocks);
        QCOMPARE(record.outcome, RockingOutcome::Rocks);
        QVERIFY2(
            std::abs(pulse.maxThetaOverAlpha - record.maxThetaOverAlpha) < 1e-5,
            qPrintable(
                QString("%1 vs %2").arg(pulse.maxThetaOverAlpha).arg(record.maxThetaOverAlpha)));
        QCOMPARE_LT(std::abs(pulse.impactTimes.front() - record.impactTimes.front()), 1e-5);
        // Scaled to a peak: the record at 0.5 g peak is the record as it is.
        const auto scaled = recordMotion(sampled(p, 1e-4, 0.5), 0.5);
        QCOMPARE(simulateRocking(m, *scaled).maxThetaOverAlpha, record.maxThetaOverAlpha);
    }
    void groundLevelIsTheGround() {
        Pulse p;
        const Accelerogram a = sampled(p, 0.01, 1.0);
        Building b;
        const Accelerogram level0 = levelMotion(b, StiffnessProfile::Uniform, 0.05, 0, a);
        QCOMPARE(level0.samples, a.samples);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument,
                                 levelMotion(b, StiffnessProfile::Uniform, 0.05, b.stories + 1, a));
        const Accelerogram roof = levelMotion(b, StiffnessProfile::Uniform, 0.05, b.stories, a);
        QVERIFY(roof.samples.size() >= a.samples.size()); // the record and its free-vibration tail
    }
};

QTEST_APPLESS_MAIN(TestRockingMap)
#include "tst_rocking_map.moc"
