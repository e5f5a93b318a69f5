// SPDX-License-Identifier: GPL-3.0-or-later
// What a 1-DOF run keeps is the recorder's choice (core/slab/SlabRecorder.h) and changes nothing
// of the run; each ready-made recorder keeps what the record flag it replaced kept
// (RunOptions::recordEvents, then sampleHistory on the result's events). The expected numbers
// are the seed's: kinstab-cli built at commit 0664031 (the last with the flag), printed by
//   kinstab-cli simulate --amplitude 1 --frequency 1 --events --history FILE
//   kinstab-cli simulate --envelope fast --amplitude 2 --frequency 3 --solver paper
//               --paper-steps 4 --events
// (JSON numbers round-trip their doubles; the history CSV has 12 significant digits). The seed's
// tau_c = 40.5402 is also Furgerson 1980 ch. V's collapse at A = 1.00 g, 1 Hz (tst_exact_solver).
// The exact solver's root solves changed after that build (issue 34, Halley's steps), which moves
// its event times by a few ulps: its values are compared to 1e-13 relative, the paper solver's
// (unchanged) bit for bit.

#include "core/excitation/EnvelopedSine.h"
#include "core/slab/FiniteResult.h"
#include "core/slab/Slab1DCase.h"
#include "core/slab/SlabRecorder.h"

#include <QtTest>

#include <cmath>
#include <cstring>
#include <stdexcept>

using namespace kinstab;

namespace {

bool sameBits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

// Both values shown when they differ.
#define QCOMPARE_BITS(a, b)                                                                        \
    QVERIFY2(sameBits((a), (b)),                                                                   \
             qPrintable(QString("%1 != %2").arg((a), 0, 'g', 17).arg((b), 0, 'g', 17)))

// The seed: the paper's moderate envelope, A = 1 g, f = 1 Hz, mu = 0.6, t* = 0.099 s.
Slab1DCase seedCase() {
    return Slab1DCase{};
}

// A paper-solver run that restarts once with H/4 before it succeeds: fast envelope, A = 2 g,
// f = 3 Hz, H = period / 4.
Slab1DCase restartingPaperCase() {
    Slab1DCase c;
    c.envelope = Envelope::fromPreset(EnvelopePreset::Fast);
    c.solver = SolverKind::Paper;
    c.paperStepsPerPeriod = 4;
    return c;
}

void compareSummaries(const SlabResult& kept, const SlabResult& bare) {
    QCOMPARE(kept.outcome, bare.outcome);
    QCOMPARE_BITS(kept.tauC, bare.tauC);
    QCOMPARE_BITS(kept.tauEnd, bare.tauEnd);
    QCOMPARE_BITS(kept.maxAbsDelta, bare.maxAbsDelta);
    QCOMPARE_BITS(kept.residualDelta, bare.residualDelta);
    QCOMPARE(kept.slipIntervals, bare.slipIntervals);
    QCOMPARE(kept.work.accelEvaluations, bare.work.accelEvaluations);
    QCOMPARE(kept.work.rootIterations, bare.work.rootIterations);
    QCOMPARE(kept.work.steps, bare.work.steps);
    QCOMPARE(kept.work.events, bare.work.events);
    QCOMPARE(kept.work.restarts, bare.work.restarts);
}

// The exact solver's values: equal to the seed's within a few ulps (see the header).
#define QCOMPARE_SEED(a, b) QCOMPARE_LE(std::abs((a) - (b)), 1e-13 * std::abs(b))

} // namespace

class TestSlabRecorder : public QObject {
    Q_OBJECT
private slots:
    void noRecorderIsTheDefaultAndChangesNothing() {
        // tau_c only: a null recorder keeps nothing; a recorder changes no bit of the summary.
        for (const Slab1DCase& c : {seedCase(), restartingPaperCase()}) {
            const double a = c.solver == SolverKind::Exact ? 1.0 : 2.0;
            const double f = c.solver == SolverKind::Exact ? 1.0 : 3.0;
            const SlabResult bare = runSlab1D(c, a, f);
            SlabEventLog log;
            compareSummaries(runSlab1D(c, a, f, {}, &log), bare);
            QCOMPARE(static_cast<long>(log.events.size()), bare.work.events);
        }
    }

    void eventLogKeepsTheSeedsEvents() {
        SlabEventLog log;
        const SlabResult r = runSlab1D(seedCase(), 1.0, 1.0, {}, &log);
        QCOMPARE(outcomeName(r.outcome), std::string("collapsed"));
        QCOMPARE_SEED(r.tauC, 40.540203379474136);
        // Six slips, each started by an onset, the first five ended by a stick, then collapse.
        QCOMPARE(log.events.size(), std::size_t(12));
        for (std::size_t i = 0; i + 1 < log.events.size(); ++i)
            QCOMPARE(eventKindName(log.events[i].kind),
                     eventKindName(i % 2 == 0 ? EventKind::SlipOnset : EventKind::Stick));
        const SlabEvent& first = log.events.front();
        QCOMPARE_SEED(first.tau, 12.161947615969051);
        QCOMPARE(first.direction, -1);
        const SlabEvent& stick = log.events[1];
        QCOMPARE_SEED(stick.tau, 13.93774192394643);
        QCOMPARE_SEED(stick.delta, -0.03458618392504874);
        QCOMPARE(stick.direction, 0);
        const SlabEvent& last = log.events.back();
        QCOMPARE(last.kind, EventKind::Collapse);
        QCOMPARE_BITS(last.tau, r.tauC);
        QCOMPARE_BITS(last.delta, 1.0);
        QCOMPARE_SEED(last.velocity, 0.3964149416193818);
        QCOMPARE(last.direction, 1);
    }

    void paperEventLogHearsOnlyTheAttemptThatSucceeds() {
        // The first attempt (H = T/4) fails to locate an event; its events are not the run's.
        SlabEventLog log;
        const SlabResult r = runSlab1D(restartingPaperCase(), 2.0, 3.0, {}, &log);
        QCOMPARE(r.work.restarts, 1L);
        QCOMPARE(log.events.size(), std::size_t(7));
        QCOMPARE(static_cast<long>(log.events.size()), r.work.events);
        QCOMPARE(log.events[0].kind, EventKind::SlipOnset);
        QCOMPARE_BITS(log.events[0].tau, 2.204986297694621);
        QCOMPARE(log.events[3].kind, EventKind::Reversal);
        QCOMPARE_BITS(log.events[3].tau, 5.576599326599323);
        QCOMPARE_BITS(log.events[3].velocity, 0.3110691844280533);
        QCOMPARE(log.events[6].kind, EventKind::Collapse);
        QCOMPARE_BITS(log.events[6].tau, 10.627104377104379);
        QCOMPARE_BITS(log.events[6].delta, 1.0219252580235625);
        QVERIFY(nonFiniteField(log.events).empty());
    }

    void historyLogIsTheSampledHistory() {
        const Slab1DCase c = seedCase();
        const EnvelopedSine a(c.envelope, 1.0, 1.0, c.tstar);
        SlabHistoryLog log(a, c.slab.mu);
        const SlabResult r = runSlab1D(c, 1.0, 1.0, {}, &log);
        const History h = log.history(r.tauEnd, 0.05);
        // sampleHistory on the events, bit for bit.
        const History want = sampleHistory(a, c.slab.mu, log.events, r.tauEnd, 0.05);
        QCOMPARE(h.samples.size(), want.samples.size());
        for (std::size_t i = 0; i < h.samples.size(); ++i) {
            QCOMPARE_BITS(h.samples[i].tau, want.samples[i].tau);
            QCOMPARE_BITS(h.samples[i].delta, want.samples[i].delta);
            QCOMPARE_BITS(h.samples[i].velocity, want.samples[i].velocity);
        }
        // The seed's CSV: 811 steps of 0.05 up to 40.5, the 12 event times, then tau_c (a
        // collapse event, counted once): 823 rows.
        QCOMPARE(h.samples.size(), std::size_t(823));
        const HistorySample& at405 = h.samples[h.samples.size() - 2];
        QCOMPARE(at405.tau, 40.5);
        QCOMPARE_LE(std::abs(at405.accel - 0.0596971863979), 1e-12);
        QCOMPARE_LE(std::abs(at405.delta - 0.983516191685), 1e-12);
        QCOMPARE_LE(std::abs(at405.velocity - 0.42343885289), 1e-11);
        QCOMPARE(at405.state, 1);
        const HistorySample& end = h.samples.back();
        QCOMPARE_BITS(end.tau, r.tauC);
        QCOMPARE_BITS(end.delta, 1.0);
        QCOMPARE_BITS(end.velocity, 0.0);
        // The step is the caller's: a step too fine for the run is refused as sampleHistory does.
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, log.history(r.tauEnd, 1e-9));
    }
};

QTEST_APPLESS_MAIN(TestSlabRecorder)
#include "tst_slab_recorder.moc"
