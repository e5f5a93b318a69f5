// SPDX-License-Identifier: GPL-3.0-or-later
// The analysis entry point (core/analysis/RunAnalysis.h): its per-point hook hands over every grid
// index exactly once with the same result as a single run there; a cancel stops it early and
// says so; parts not asked for are not computed; its A_crit(f) equals the single-frequency search
// (core/sweep/CriticalAmplitude.h) at each frequency. Every expected number here is an
// independent direct run of the same solver, never a typed-in value.

#include "core/analysis/RunAnalysis.h"
#include "core/codes/Building.h"
#include "core/sweep/ParallelFor.h"

#include <QtTest>

#include <atomic>
#include <bit>
#include <mutex>
#include <stdexcept>

using namespace kinstab;

namespace {

// A few points of the paper's grid (Furgerson 1980, Fig. 28) with the moderate envelope: some
// collapse, some do not.
AnalysisRequest smallRequest() {
    AnalysisRequest q;
    q.grid = {linspaceStep(0.7, 1.1, 0.1), linspaceStep(0.5, 1.0, 0.25)};
    q.criticalFrequencies = {0.5, 1.0};
    q.criticalSearch = CriticalSearch{0.0, 1.5, 0.01, 1e-5};
    q.threads = 2;
    return q;
}

bool sameBits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

} // namespace

class TestAnalysis : public QObject {
    Q_OBJECT
private slots:
    void hookGetsEveryIndexOnceWithItsResult() {
        AnalysisRequest q = smallRequest();
        q.parts.surface = true;
        AnalysisControl control;
        std::mutex mutex;
        std::vector<int> calls(q.grid.size(), 0);
        std::vector<PointResult> seen(q.grid.size());
        control.onPoint = [&](std::size_t k, const PointResult& r) {
            std::lock_guard lock(mutex);
            ++calls.at(k);
            seen[k] = r;
        };
        const AnalysisResult r = runAnalysis(q, control);
        QVERIFY(r.surface && !r.cancelled);
        QCOMPARE(control.done(), q.grid.size());
        QCOMPARE(control.total(), q.grid.size());
        const std::size_t nf = q.grid.frequencies.size();
        for (std::size_t k = 0; k < q.grid.size(); ++k) {
            QCOMPARE(calls[k], 1);
            const double a = q.grid.amplitudes[k / nf], f = q.grid.frequencies[k % nf];
            const SlabResult direct = runSlab1D(q.slab, a, f);
            QCOMPARE(seen[k].outcome, direct.outcome);
            QCOMPARE(r.surface->points[k].outcome, direct.outcome);
            if (direct.outcome == Outcome::Collapsed) {
                QVERIFY(sameBits(seen[k].tauC, direct.tauC));
                QVERIFY(sameBits(r.surface->points[k].tauC, direct.tauC));
            }
        }
    }

    void cancelStopsEarlyAndSaysSo() {
        AnalysisRequest q = smallRequest();
        q.grid = {linspaceStep(0.5, 1.5, 0.02), linspaceStep(0.25, 2.25, 0.05)}; // 2091 points
        q.parts.surface = true;
        q.parts.criticalCurve = true;
        AnalysisControl control;
        control.onPoint = [&control](std::size_t, const PointResult&) { control.cancel(); };
        const AnalysisResult r = runAnalysis(q, control);
        QVERIFY(r.cancelled);
        QVERIFY(r.surface && r.surface->cancelled);
        // Each of the 2 threads finishes at most the point it holds after the first one.
        QVERIFY(r.surface->completed <= 3);
        QVERIFY(control.done() < control.total());
        QVERIFY(!r.critical); // never started after the cancel
    }

    void partsNotAskedForAreNotComputed() {
        AnalysisRequest q = smallRequest();
        q.parts.criticalCurve = true; // the grid and frequencies are set, only the curve asked
        AnalysisControl control;
        std::atomic<int> points{0};
        control.onPoint = [&points](std::size_t, const PointResult&) { ++points; };
        const AnalysisResult r = runAnalysis(q, control);
        QVERIFY(!r.surface && !r.check && !r.record && !r.checkError);
        QCOMPARE(points.load(), 0);
        QCOMPARE(control.total(), q.criticalFrequencies.size());
        QVERIFY(r.critical);

        AnalysisRequest s = smallRequest();
        s.parts.surface = true;
        AnalysisControl c2;
        const AnalysisResult onlySurface = runAnalysis(s, c2);
        QVERIFY(onlySurface.surface && !onlySurface.critical && !onlySurface.check);
        QCOMPARE(c2.total(), s.grid.size());
    }

    void aFailedCheckKeepsTheSurface() {
        AnalysisRequest q = smallRequest();
        q.parts.surface = true;
        q.parts.designCheck = true;
        CodeResult bad;
        bad.code = "ubc1976";
        bad.periodSeconds = 0; // no building frequency 1/T
        q.codes = {bad};
        AnalysisControl control;
        const AnalysisResult r = runAnalysis(q, control);
        QVERIFY(r.surface && r.surface->completed == q.grid.size());
        QVERIFY(!r.check && r.checkError);
        try {
            std::rethrow_exception(r.checkError);
        } catch (const InputError& e) {
            QVERIFY(QString(e.what()).contains("ubc1976.period_s"));
        }
        QCOMPARE(control.done(), control.total());
    }

    void curveEqualsSingleSearches() {
        AnalysisRequest q = smallRequest();
        q.parts.criticalCurve = true;
        AnalysisControl control;
        const AnalysisResult r = runAnalysis(q, control);
        QVERIFY(r.critical);
        long runs = 0;
        for (std::size_t j = 0; j < q.criticalFrequencies.size(); ++j) {
            const CriticalResult direct = criticalAmplitude(
                slab1DPoint(q.slab), q.criticalFrequencies[j], q.slab.slab.mu, q.criticalSearch);
            runs += direct.runs;
            QCOMPARE(r.critical->amplitude[j].has_value(), direct.amplitude.has_value());
            if (direct.amplitude) QVERIFY(sameBits(*r.critical->amplitude[j], *direct.amplitude));
        }
        QCOMPARE(r.critical->runs, runs);
        QCOMPARE(r.scanFrom, q.slab.slab.mu);
    }

    void poolRethrowsTheFirstFailureInIndexOrder() {
        // As a plain loop would: of the bodies that throw (3 and 7), index 3's exception.
        for (int threads : {1, 2, 4}) {
            try {
                parallelFor(20, threads, nullptr, [](std::size_t k) {
                    if (k == 3 || k == 7) throw std::runtime_error(std::to_string(k));
                });
                QFAIL("no exception");
            } catch (const std::runtime_error& e) {
                QCOMPARE(QString(e.what()), QString("3"));
            }
        }
    }
};

QTEST_GUILESS_MAIN(TestAnalysis)
#include "tst_analysis.moc"
