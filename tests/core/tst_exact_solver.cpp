// SPDX-License-Identifier: GPL-3.0-or-later
// The event-driven exact solver (docs/theory.md §4, §6): the paper's critical ratio, and agreement
// with an independent quadrature reference to 1e-9 relative in tau_c.

#include "QuadratureReference.h"
#include "core/excitation/EnvelopedSine.h"
#include "core/slab/ExactSolver.h"
#include "core/slab/History.h"
#include "core/slab/Slab1DCase.h"

#include <QtTest>
#include <cmath>
#include <numbers>

using namespace kinstab;

class TestExactSolver : public QObject {
    Q_OBJECT
private slots:
    void paperCriticalRatio() {
        // Furgerson 1980 ch. V: moderate envelope, mu = 0.6, t* = 0.099, f = 1 Hz:
        // A = 0.95 is stable and A = 1.00 collapses ("critical ratio 0.95").
        Slab1DCase c;
        QCOMPARE(runSlab1D(c, 0.95, 1.0).outcome, Outcome::Stable);
        const SlabResult r = runSlab1D(c, 1.00, 1.0);
        QCOMPARE(r.outcome, Outcome::Collapsed);
        QVERIFY(r.tauC > 0 && r.tauC < 113.8);
    }
    void noSlipBelowMu() {
        Slab1DCase c;
        const SlabResult r = runSlab1D(c, 0.59, 1.0);
        QCOMPARE(r.outcome, Outcome::Stable);
        QCOMPARE(r.slipIntervals, 0);
        QCOMPARE(r.maxAbsDelta, 0.0);
    }
    void agreesWithReference_data() {
        QTest::addColumn<int>("preset");
        QTest::addColumn<double>("A");
        QTest::addColumn<double>("f");
        QTest::addColumn<double>("mu");
        for (int p = 0; p < 3; ++p)
            for (double A : {0.8, 1.0, 1.15, 1.6, 3.0})
                for (double f : {0.5, 1.125, 2.0}) {
                    const QByteArray name =
                        QByteArray::fromStdString(presetName(EnvelopePreset(p))) +
                        " A=" + QByteArray::number(A) + " f=" + QByteArray::number(f);
                    QTest::newRow(name.constData()) << p << A << f << 0.6;
                }
        QTest::newRow("moderate A=1.2 f=0.7 mu=0.3") << 1 << 1.2 << 0.7 << 0.3;
        QTest::newRow("slow A=0.5 f=1.5 mu=0.2") << 2 << 0.5 << 1.5 << 0.2;
    }
    void agreesWithReference() {
        QFETCH(int, preset);
        QFETCH(double, A);
        QFETCH(double, f);
        QFETCH(double, mu);
        const EnvelopedSine a(Envelope::fromPreset(EnvelopePreset(preset)), A, f, 0.099);
        SlabParams p;
        p.mu = mu;
        const SlabResult exact = solveExact(a, p);
        const double period = 2.0 * std::numbers::pi / a.omega();
        testing::QuadratureReference ref(a, mu, 1.0, period / 64.0);
        const testing::ReferenceResult want = ref.run(5000.0);
        QCOMPARE(outcomeName(exact.outcome), outcomeName(want.outcome));
        QCOMPARE(exact.slipIntervals, want.slipIntervals);
        if (want.outcome == Outcome::Collapsed)
            QCOMPARE_LE(std::abs(exact.tauC / want.tauC - 1.0), 1e-9);
        else
            QCOMPARE_LE(std::abs(exact.residualDelta - want.residualDelta), 1e-9);
    }
    void eventsAreConsistent() {
        // Events alternate correctly, and the history rebuilt from them is continuous.
        const EnvelopedSine a(Envelope::fromPreset(EnvelopePreset::Moderate), 1.05, 1.0, 0.099);
        SlabParams p;
        SlabEventLog log;
        const SlabResult r = solveExact(a, p, {}, &log);
        const std::vector<SlabEvent>& events = log.events;
        QVERIFY(events.size() >= 3);
        QCOMPARE(events.back().kind, EventKind::Collapse);
        int onsets = 0;
        for (std::size_t i = 0; i < events.size(); ++i) {
            const SlabEvent& e = events[i];
            if (e.kind == EventKind::SlipOnset || e.kind == EventKind::Reversal) ++onsets;
            if (i > 0) QVERIFY(e.tau >= events[i - 1].tau);
            if (e.kind == EventKind::Stick)
                QCOMPARE_LE(std::abs(std::abs(a.accel(e.tau))), 0.6 + 1e-12);
            if (e.kind == EventKind::SlipOnset)
                QCOMPARE_LE(std::abs(std::abs(a.accel(e.tau)) - 0.6), 1e-12);
        }
        QCOMPARE(onsets, r.slipIntervals);
        const History h = sampleHistory(a, p.mu, events, r.tauEnd, 0.01);
        for (std::size_t i = 1; i < h.samples.size(); ++i) {
            const double dt = h.samples[i].tau - h.samples[i - 1].tau;
            QCOMPARE_LE(std::abs(h.samples[i].delta - h.samples[i - 1].delta), 2.0 * dt + 1e-12);
        }
        QCOMPARE_LE(std::abs(std::abs(h.samples.back().delta) - 1.0), 1e-9);
    }
    void collapseFactorScalings() {
        Slab1DCase c;
        const SlabResult r = runSlab1D(c, 1.1, 1.0);
        QCOMPARE(r.outcome, Outcome::Collapsed);
        for (TauScale s : {TauScale::TauRise, TauScale::TauMax, TauScale::TauDur, TauScale::One}) {
            c.scale = s;
            QCOMPARE(collapseFactor(c.tauRef(), r), c.envelope.tauRef(s, c.tstar) / r.tauC);
        }
        QCOMPARE(collapseFactor(37.89, runSlab1D(c, 0.9, 1.0)), 0.0);
    }
    void nonDecayingNeedsDuration() {
        const EnvelopedSine a(Envelope{0.0, 0.4, std::nullopt}, 1.0, 1.0, 0.099);
        SlabParams p;
        const SlabResult r = solveExact(a, p);
        QCOMPARE(r.outcome, Outcome::Failed);
        QVERIFY(QString::fromStdString(r.failure).contains("duration"));
        p.duration = 50.0;
        const SlabResult capped = solveExact(a, p);
        QVERIFY(capped.outcome == Outcome::Stable || capped.outcome == Outcome::Collapsed);
    }
};

QTEST_APPLESS_MAIN(TestExactSolver)
#include "tst_exact_solver.moc"
