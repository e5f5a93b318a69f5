// SPDX-License-Identifier: GPL-3.0-or-later
// Long runs and extreme inputs of the 1-DOF exact solver: no NaN, no false collapse, no hang.
// Each case reproduces a failure seen before the envelope's integrals were written so that no
// intermediate leaves the range of double (a long slip at tau > 709.78 / (d t*) multiplied an
// overflowed expm1 by an underflowed exponential: inf x 0 = NaN).

#include "QuadratureReference.h"
#include "core/base/InternalError.h"
#include "core/excitation/EnvelopedSine.h"
#include "core/excitation/FrequencyRange.h"
#include "core/io/ResultJson.h"
#include "core/slab/ExactSolver.h"
#include "core/slab/FiniteResult.h"
#include "core/slab/Slab1DCase.h"
#include "core/sweep/CriticalAmplitude.h"
#include "core/sweep/Sweep.h"

#include <QtTest>
#include <cmath>
#include <limits>

using namespace kinstab;

namespace {
Slab1DCase fastCase(double mu) {
    Slab1DCase c;
    c.envelope = Envelope::fromPreset(EnvelopePreset::Fast);
    c.slab.mu = mu;
    return c;
}
} // namespace

class TestLongTimeNumerics : public QObject {
    Q_OBJECT
private slots:
    void longStableRunIsFinite() {
        // Fast envelope, A = 3 g, f = 30 Hz, mu = 0.05: the slab slips until tau ~ 3720, past
        // 709.78 / ((beta - alpha) t*) = 3603. Before, a stick event there had tau = NaN and the
        // run ended "stable" with residual and end time NaN.
        SlabEventLog log;
        const SlabResult r = runSlab1D(fastCase(0.05), 3.0, 30.0, {}, &log);
        QCOMPARE(outcomeName(r.outcome), outcomeName(Outcome::Stable));
        QVERIFY2(nonFiniteField(r).empty(), nonFiniteField(r).c_str());
        QVERIFY(r.tauEnd > 3603.0);
        QCOMPARE_LT(std::abs(r.residualDelta), 1.0);
        QVERIFY2(nonFiniteField(log.events).empty(), nonFiniteField(log.events).c_str());
        for (std::size_t i = 1; i < log.events.size(); ++i)
            QVERIFY(log.events[i].tau >= log.events[i - 1].tau);
    }
    void noFalseCollapse_data() {
        QTest::addColumn<double>("A");
        // Fast envelope, mu = 0.1, f = 6 Hz: before, A = 3.43098 "collapsed" with tau_c NaN
        // (and the critical search stopped there); A/mu 34.3-34.6 was affected.
        for (double a = 3.40; a <= 3.4601; a += 0.005)
            QTest::newRow(QByteArray::number(a).constData()) << a;
        QTest::newRow("3.43098") << 3.43098;
        QTest::newRow("3.44") << 3.44;
    }
    void noFalseCollapse() {
        QFETCH(double, A);
        const SlabResult r = runSlab1D(fastCase(0.1), A, 6.0);
        QCOMPARE(outcomeName(r.outcome), outcomeName(Outcome::Stable));
        QVERIFY2(nonFiniteField(r).empty(), nonFiniteField(r).c_str());
    }
    void criticalEdgeAtSixHertz() {
        // The true edge lies between 4.610566 and 4.610586 g (two independent references, one
        // in 40-digit arithmetic): below it stable, above it collapsed, with a finite tau_c.
        const Slab1DCase c = fastCase(0.1);
        QCOMPARE(outcomeName(runSlab1D(c, 4.61055, 6.0).outcome), outcomeName(Outcome::Stable));
        const SlabResult r = runSlab1D(c, 4.61060, 6.0);
        QCOMPARE(outcomeName(r.outcome), outcomeName(Outcome::Collapsed));
        QVERIFY(std::isfinite(r.tauC) && r.tauC > 0.0);
        // The search near the edge: bracket from 4.6 g, refined to 1e-6 g.
        const CriticalResult crit =
            criticalAmplitude(slab1DPoint(c), 6.0, 0.1, {4.6, 4.62, 0.01, 1e-6});
        QVERIFY(crit.amplitude);
        QVERIFY2(*crit.amplitude > 4.610566 - 1e-6 && *crit.amplitude < 4.610586 + 1e-6,
                 QByteArray::number(*crit.amplitude, 'g', 10).constData());
    }
    void sMaxFiniteBelowTheFrequencyLimit_data() {
        QTest::addColumn<int>("preset");
        QTest::addColumn<double>("f");
        for (int p = 0; p < 3; ++p)
            for (double f : {kMinFrequencyHz, 1e-4, 1e-6})
                QTest::newRow(
                    (presetName(static_cast<EnvelopePreset>(p)) + " " + std::to_string(f)).c_str())
                    << p << f;
    }
    void sMaxFiniteBelowTheFrequencyLimit() {
        // Before, f <= 1e-4 Hz looped for ever: e(tau) underflowed in the second half-period,
        // e'/e was 0/0 and the walk over half-period peaks never met a smaller NaN. The
        // command line refuses f below kMinFrequencyHz; the core must still end, finite.
        QFETCH(int, preset);
        QFETCH(double, f);
        const EnvelopedSine a(Envelope::fromPreset(static_cast<EnvelopePreset>(preset)), 1.0, f,
                              0.099);
        QVERIFY(std::isfinite(a.sMax()) && a.sMax() > 0.0);
        // The peak of |a| is A = 1 g (S_max normalizes it): sampled on a fine grid around the
        // envelope's peak, it is approached but never exceeded.
        double best = 0.0;
        const Envelope env = Envelope::fromPreset(static_cast<EnvelopePreset>(preset));
        const double tMax = 20.0 / (env.alpha * 0.099); // e^{-20} of the envelope's decay left
        for (int k = 1; k <= 20000; ++k)
            best = std::max(best, std::abs(a.accel(tMax * k / 20000.0)));
        QVERIFY2(best <= 1.0 + 1e-12 && best > 0.99, QByteArray::number(best).constData());
        const SlabResult r = solveExactFor(a, 0.5);
        QVERIFY2(nonFiniteField(r).empty(), nonFiniteField(r).c_str());
        QVERIFY(r.outcome == Outcome::Stable || r.outcome == Outcome::Collapsed);
    }
    void frequencyLimitRefused() {
        QVERIFY(validateEnvelopedSine(1.0, kMinFrequencyHz, 0.099).empty());
        QVERIFY(QString::fromStdString(validateEnvelopedSine(1.0, 1e-4, 0.099)).contains("0.001"));
        QVERIFY(!checkInput(kFrequencyInput, 0.999e-3).empty());
        QVERIFY(checkInput(kFrequencyInput, 1000.0).empty());
    }
    void bisectionBelowOneUlpEnds() {
        // A tolerance below double resolution (1e-17 g at A ~ 1) cannot loop: the search stops
        // at adjacent doubles. The point function: collapse at and above 0.7 g.
        long runs = 0;
        const PointFunction step = [&](double a, double) {
            ++runs;
            return PointResult{a >= 0.7 ? Outcome::Collapsed : Outcome::Stable, 1.0};
        };
        const CriticalResult r = criticalAmplitude(step, 1.0, 0.6, {0.0, 5.0, 0.01, 1e-17});
        QVERIFY(r.amplitude);
        QCOMPARE_LE(std::abs(*r.amplitude - 0.7), 4.0 * std::numeric_limits<double>::epsilon());
        QVERIFY(runs < 12 + kMaxHalvings);
    }
    void scanBeyondItsBoundRefused() {
        // A scan past the bound is an error, not hours of runs.
        const PointFunction never = [](double, double) { return PointResult{Outcome::Stable, 0}; };
        QVERIFY_THROWS_EXCEPTION(InternalError,
                                 criticalAmplitude(never, 1.0, 0.0, {0.0, 5.0, 1e-9, 1e-10}));
    }
    void nonFiniteResultIsAnInternalFailure() {
        // A collapse without a finite time is never a verdict: the solver's result becomes an
        // internal failure, the writers refuse it, and requireSound names the case.
        SlabResult r;
        r.outcome = Outcome::Collapsed;
        r.tauEnd = 10.0;
        QVERIFY_THROWS_EXCEPTION(InternalError, slabResultJson(r, 27.78));
        QVERIFY_THROWS_EXCEPTION(InternalError, requireSound(r, "case X"));
        try {
            requireSound(r, "case X");
        } catch (const InternalError& e) {
            QVERIFY(QString(e.what()).contains("case X"));
            QVERIFY(QString(e.what()).contains("tau_c"));
        }
        failIfNonFinite(r);
        QCOMPARE(outcomeName(r.outcome), outcomeName(Outcome::Failed));
        QVERIFY(isInternalFailure(r));
        QVERIFY(QString::fromStdString(r.failure).startsWith("internal error: non-finite tau_c"));
        SlabResult stable;
        stable.outcome = Outcome::Stable;
        stable.residualDelta = std::numeric_limits<double>::quiet_NaN();
        QVERIFY_THROWS_EXCEPTION(InternalError, slabResultJson(stable, 27.78));
        stable.residualDelta = 0.25;
        const std::vector<SlabEvent> events{
            {std::numeric_limits<double>::infinity(), EventKind::Stick, 0, 0, 0}};
        QVERIFY_THROWS_EXCEPTION(InternalError, eventsJson(events));
        QVERIFY(QString::fromStdString(nonFiniteField(events)).contains("event 0 (stick) tau"));
        failIfNonFinite(stable, events);
        QVERIFY(isInternalFailure(stable));
        QVERIFY(QString::fromStdString(stable.failure).contains("event 0 (stick) tau"));
    }

private:
    static SlabResult solveExactFor(const EnvelopedSine& a, double mu) {
        SlabParams p;
        p.mu = mu;
        return solveExact(a, p);
    }
};

QTEST_APPLESS_MAIN(TestLongTimeNumerics)
#include "tst_long_time_numerics.moc"
