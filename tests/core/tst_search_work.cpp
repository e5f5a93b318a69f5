// SPDX-License-Identifier: GPL-3.0-or-later
// The bound on an A_crit search's work (core/sweep/SearchWork.h, issue 31): the half-periods a
// run walks come from e(t) <= exp(-alpha t) (Furgerson 1980, ch. IV), worked here by hand; a
// search whose inputs each lie in range but whose product would run for minutes is refused
// naming the frequency, and the paper's own searches are far inside the bound.

#include "core/sweep/SearchWork.h"

#include <QtTest>

#include <cmath>

using namespace kinstab;

class TestSearchWork : public QObject {
    Q_OBJECT
private slots:
    void halfPeriodsFollowTheEnvelopesDecay() {
        Slab1DCase c; // moderate envelope: alpha 0.15 1/s; mu 0.6 (SlabParams' default)
        c.slab.mu = 0.6;
        // A e(t) < mu once t > ln(A / mu) / alpha = ln(5 / 0.6) / 0.15 = 14.135 s; at 2 Hz that
        // is 2 * 2 * 14.135 = 56.54 half-periods.
        const double expected = 4.0 * std::log(5.0 / 0.6) / c.envelope.alpha;
        QCOMPARE(sineHalfPeriods(c, 5.0, {2.0, 1.0, 1.0}), expected);
        QCOMPARE(sineHalfPeriods(c, 0.5, {2.0, 1.0, 1.0}), 0.0); // below mu nothing slips
        // tau_out = 10 at t* = 0.099 s ends the run at 0.99 s: 3.96 half-periods.
        c.slab.duration = 10.0;
        QCOMPARE(sineHalfPeriods(c, 5.0, {2.0, 1.0, 1.0}), 2.0 * 2.0 * 0.99);
    }
    void runsAreTheScanAndTheHalvings() {
        // From mu = 0.6 to 5 g in 0.01 g steps: 440 points; 0.01 / 1e-6 halves in 14 steps; and
        // the first run at the scan's start.
        QCOMPARE(searchRuns(0.6, CriticalSearch{}), 1L + 440L + 14L);
    }
    void thePapersSearchesFitAndAThousandHertzDoesNot() {
        Slab1DCase c;
        c.slab.mu = 0.6;
        const CriticalSearch s;
        // The paper's frequencies (0.5-2 Hz) and the codes' 1/T of a 0.02 s building, 50 Hz.
        for (double f : {0.5, 1.0, 2.0, 50.0})
            QVERIFY2(checkSearchWork(c, c.slab.mu, s, {f, 1.0, 1.0}).empty(),
                     qPrintable(QString::number(f)));
        const InputProblem p = checkSearchWork(c, c.slab.mu, s, {1000.0, 1.0, 1.0});
        QCOMPARE(p.key, std::string("frequency"));
        QCOMPARE(p.value, 1000.0);
        QVERIFY(p.why.find("half-periods") != std::string::npos);
        // The planar model's cost factor moves the same search past the bound.
        QVERIFY(checkSearchWork(c, c.slab.mu, s, {50.0, 1.0, 1.0}).empty());
        QVERIFY(!checkSearchWork(c, c.slab.mu, s, {50.0, 1.0, kPlanarCostFactor}).empty());
    }
    void aSlowEnvelopeIsRefusedAtAModerateFrequency() {
        Slab1DCase c;
        c.slab.mu = 0.6;
        c.envelope = Envelope{1e-3, 1e4, std::nullopt}; // an e-folding time of 1000 s
        QVERIFY(!checkSearchWork(c, c.slab.mu, CriticalSearch{}, {100.0, 1.0, 1.0}).empty());
    }
};

QTEST_MAIN(TestSearchWork)
#include "tst_search_work.moc"
