// SPDX-License-Identifier: GPL-3.0-or-later
// Sweeps over (A, f) grids (docs/theory.md §4, §6.6): same numbers as single runs, on all threads,
// cancellable; the shape of the paper's gamma_c surfaces (Figs. 28-34); A_crit.

#include "core/sweep/CriticalAmplitude.h"
#include "core/sweep/Sweep.h"

#include <QtTest>
#include <atomic>
#include <cmath>

using namespace kinstab;

namespace {
SweepGrid paperGrid() {
    return {linspaceStep(0.70, 1.15, 0.05), linspaceStep(0.5, 1.125, 0.125)};
}
Slab1DCase withPreset(EnvelopePreset p) {
    Slab1DCase c;
    c.envelope = Envelope::fromPreset(p);
    return c;
}
} // namespace

class TestSweep : public QObject {
    Q_OBJECT
private slots:
    void listSyntax() {
        // docs/user-guide.md "The command line": start:stop:step includes stop when it lies on the
        // grid within 1e-9.
        QCOMPARE(parseList("0.7:1.15:0.05").values.size(), std::size_t(10));
        QCOMPARE(parseList("0.5:2.25:0.0078125").values.size(), std::size_t(225));
        QCOMPARE(parseList("0.5:1.5:0.00390625").values.size(), std::size_t(257));
        QCOMPARE(parseList("1, 2.5,3").values, (std::vector<double>{1, 2.5, 3}));
        QVERIFY(!parseList("").error.empty());
        QVERIFY(!parseList("1,x").error.empty());
        QVERIFY(!parseList("1:0:0.1").error.empty());
        QVERIFY(!parseList("0:1:0").error.empty());
        QVERIFY(!parseList("nan").error.empty());
        QVERIFY(QString::fromStdString(validateGrid({{}, {1.0}})).contains("amplitudes"));
        QVERIFY(QString::fromStdString(validateGrid({{1.0}, {-1.0}})).contains("frequencies"));
    }
    void sweepEqualsSingleRuns() {
        const Slab1DCase c = withPreset(EnvelopePreset::Moderate);
        const SweepGrid g = paperGrid();
        const SweepResult r = runSweep(g, slab1DPoint(c), nullptr, 2);
        QCOMPARE(r.completed, g.size());
        QVERIFY(!r.cancelled);
        for (std::size_t i = 0; i < g.amplitudes.size(); ++i)
            for (std::size_t j = 0; j < g.frequencies.size(); ++j) {
                const SlabResult s = runSlab1D(c, g.amplitudes[i], g.frequencies[j]);
                QCOMPARE(r.at(i, j).outcome, s.outcome);
                if (s.outcome == Outcome::Collapsed) QCOMPARE(r.at(i, j).tauC, s.tauC);
            }
    }
    void progressAndCancel() {
        const Slab1DCase c = withPreset(EnvelopePreset::Moderate);
        const SweepGrid g{linspaceStep(0.5, 1.5, 0.01), linspaceStep(0.25, 2.25, 0.02)};
        SweepControl control;
        std::atomic<std::size_t> lastProgress{0};
        control.onProgress = [&](std::size_t done, std::size_t total) {
            lastProgress = done;
            if (done >= total / 10) control.cancel();
        };
        const SweepResult r = runSweep(g, slab1DPoint(c), &control, 2);
        QVERIFY(r.cancelled);
        QVERIFY(r.completed >= g.size() / 10);
        QVERIFY(r.completed < g.size());
        std::size_t done = 0;
        for (unsigned char d : r.done)
            done += d;
        QCOMPARE(done, r.completed);
        QCOMPARE(lastProgress.load() <= r.completed, true);
    }
    void surfaceShape_data() {
        QTest::addColumn<int>("preset");
        QTest::newRow("Fig. 28/31 fast") << int(EnvelopePreset::Fast);
        QTest::newRow("Fig. 29/32 moderate") << int(EnvelopePreset::Moderate);
        QTest::newRow("Fig. 30/33 slow") << int(EnvelopePreset::Slow);
    }
    void surfaceShape() {
        // Furgerson 1980 ch. IV, Figs. 28-34: for a given f, gamma_c rises steeply with A past a
        // critical amplitude; at fixed A it falls with f. On the paper's grid: the collapsed region
        // is a staircase (collapsed at (A, f) => collapsed at larger A and at lower f), and gamma_c
        // at the top amplitude is higher at the lowest frequency than at the highest.
        QFETCH(int, preset);
        const Slab1DCase c = withPreset(EnvelopePreset(preset));
        const SweepGrid g = paperGrid();
        const SweepResult r = runSweep(g, slab1DPoint(c), nullptr, 2);
        const std::vector<double> gamma = collapseFactors(r, c.tauRef());
        const std::size_t na = g.amplitudes.size(), nf = g.frequencies.size();
        auto collapsed = [&](std::size_t i, std::size_t j) {
            return r.at(i, j).outcome == Outcome::Collapsed;
        };
        for (std::size_t i = 0; i < na; ++i)
            for (std::size_t j = 0; j < nf; ++j) {
                if (!collapsed(i, j)) continue;
                if (i + 1 < na) QVERIFY2(collapsed(i + 1, j), "collapse region not monotone in A");
                if (j > 0) QVERIFY2(collapsed(i, j - 1), "collapse region not monotone in f");
            }
        QVERIFY(!collapsed(0, 0));     // A = 0.70 never collapses on this grid
        QVERIFY(collapsed(na - 1, 0)); // A = 1.15 at 0.5 Hz always does
        QVERIFY(gamma[(na - 1) * nf + 0] > gamma[(na - 1) * nf + nf - 1]);
        for (std::size_t j = 0; j < nf; ++j) {
            std::size_t first = na;
            for (std::size_t i = 0; i < na; ++i)
                if (collapsed(i, j)) {
                    first = i;
                    break;
                }
            if (first + 1 < na) QVERIFY(gamma[(na - 1) * nf + j] > gamma[first * nf + j]);
        }
    }
    void criticalAmplitudePaper() {
        // The paper's critical ratio at 1 Hz, moderate envelope: 0.95 < A_crit <= 1.00.
        const Slab1DCase c = withPreset(EnvelopePreset::Moderate);
        const PointFunction p = slab1DPoint(c);
        const CriticalResult r = criticalAmplitude(p, 1.0, c.slab.mu);
        QVERIFY(r.amplitude.has_value());
        QVERIFY(*r.amplitude > 0.95 && *r.amplitude <= 1.0);
        // It is a transition: just below stable, at it collapsed.
        QCOMPARE(p(*r.amplitude - 2e-6, 1.0).outcome, Outcome::Stable);
        QCOMPARE(p(*r.amplitude, 1.0).outcome, Outcome::Collapsed);
    }
    void criticalAmplitudeRisesWithFrequency() {
        const Slab1DCase c = withPreset(EnvelopePreset::Moderate);
        const PointFunction p = slab1DPoint(c);
        double previous = 0;
        for (double f : {0.5, 0.75, 1.0, 1.25}) {
            const CriticalResult r = criticalAmplitude(p, f, c.slab.mu);
            QVERIFY(r.amplitude.has_value());
            QVERIFY(*r.amplitude > previous);
            previous = *r.amplitude;
        }
    }
    void criticalAmplitudeNoneBelowLimit() {
        const Slab1DCase c = withPreset(EnvelopePreset::Moderate);
        CriticalSearch s;
        s.to = 0.7;
        QVERIFY(!criticalAmplitude(slab1DPoint(c), 1.0, c.slab.mu, s).amplitude.has_value());
    }
};

QTEST_APPLESS_MAIN(TestSweep)
#include "tst_sweep.moc"
