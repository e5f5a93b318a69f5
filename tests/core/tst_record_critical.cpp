// SPDX-License-Identifier: GPL-3.0-or-later
// The critical scale of a record (core/sweep/CriticalRecordScale.h): the smallest peak (g) of
// the scaled driving motion that collapses the 1-DOF slab, checked against an independent
// brute-force scan in steps of 0.001 g (each step a direct exact-solver run of the scaled
// record), and the record's design-check verdicts against the code ratios.

#include "core/check/RecordCheck.h"
#include "core/excitation/FloorFilter.h"
#include "core/excitation/RecordedMotion.h"
#include "core/records/RecordReader.h"
#include "core/slab/ExactSolver.h"
#include "core/slab/RecordRun.h"
#include "core/sweep/CriticalRecordScale.h"

#include "RecordMotions.h"

#include <QtTest>

#include <cmath>
#include <cstring>
#include <memory>

using namespace kinstab;

namespace {

using testing::motionOf;

bool collapsesAt(const Accelerogram& m, const Slab1DCase& c, double peak) {
    return solveExact(RecordedMotion(m, c.tstar, peak), c.slab).outcome == Outcome::Collapsed;
}

// First collapsing peak on the grid mu + k h (independent of CriticalAmplitude's scan).
std::optional<double> bruteForce(const Accelerogram& m, const Slab1DCase& c, double h, double to) {
    for (long k = 0;; ++k) {
        const double p = c.slab.mu + static_cast<double>(k) * h;
        if (p > to) return std::nullopt;
        if (collapsesAt(m, c, p)) return p;
    }
}

bool sameBits(double x, double y) {
    return std::memcmp(&x, &y, sizeof x) == 0;
}

} // namespace

class TestRecordCritical : public QObject {
    Q_OBJECT
private slots:
    void againstBruteForce_data() {
        QTest::addColumn<QString>("file");
        QTest::addColumn<double>("floorPeriod"); // 0: the ground record itself
        QTest::addColumn<double>("mu");
        QTest::newRow("El Centro 1940 180, ground, mu 0.6")
            << "RSN6_IMPVALL.I_I-ELC180.AT2" << 0.0 << 0.6;
        QTest::newRow("Pacoima Dam 164, floor T 1 s, mu 0.6")
            << "RSN77_SFERN_PUL164.AT2" << 1.0 << 0.6;
        QTest::newRow("Pacoima Dam 164, ground, mu 0.3") << "RSN77_SFERN_PUL164.AT2" << 0.0 << 0.3;
    }
    void againstBruteForce() {
        QFETCH(QString, file);
        QFETCH(double, floorPeriod);
        QFETCH(double, mu);
        const Accelerogram m = motionOf(file.toStdString(), floorPeriod);
        Slab1DCase c;
        c.slab.mu = mu;
        const CriticalSearch search{0.0, 5.0, 0.01, 1e-6};
        const RecordCriticalScale r = criticalRecordScale(c, m, search);
        const double h = 1e-3;
        const std::optional<double> brute = bruteForce(m, c, h, search.to);
        QVERIFY(brute);
        QVERIFY(r.peak);
        qInfo("%s: critical peak %.6f g (factor %.4f, %ld runs), brute force first collapse %.3f g",
              qPrintable(file), *r.peak, *r.factor, r.runs, *brute);
        // The brute force's step below its first collapse was stable, so the transition lies
        // within one step below it.
        QCOMPARE_GT(*r.peak, *brute - h - search.tolerance);
        QCOMPARE_LE(*r.peak, *brute + search.tolerance);
        QVERIFY(collapsesAt(m, c, *r.peak));
        QVERIFY(!collapsesAt(m, c, *r.peak - 2.0 * search.tolerance));
        QCOMPARE(*r.factor, *r.peak / std::abs(m.peak().value));
    }
    void nothingCollapsesBelowTheLimit() {
        const Accelerogram m = motionOf("RSN6_IMPVALL.I_I-ELC180.AT2", 0.0);
        Slab1DCase c;
        const RecordCriticalScale r =
            criticalRecordScale(c, m, CriticalSearch{0.0, 0.65, 0.01, 1e-6});
        QVERIFY(!r.peak);
        QVERIFY(!r.factor);
        // Below mu nothing slips, so the scan runs from mu = 0.6 to 0.65 in 0.01 steps: 6 runs
        // (0.6, 0.61, ..., 0.65), though (0.65 - 0.6) / 0.01 rounds to 5.000000000000004.
        QCOMPARE(r.runs, 6L);
    }
    // Issue 34: a search builds the record's samples once, and each of its runs (a scaled view
    // formed lazily as far as the run reaches) gives the bits of a run on a motion formed whole.
    void searchBuildsTheMotionOnceAndRunsAsBefore() {
        const Accelerogram m = motionOf("RSN77_SFERN_PUL164.AT2", 1.0);
        Slab1DCase c;
        c.slab.mu = 0.6;
        const long before = RecordSamples::constructed();
        const RecordCriticalScale r =
            criticalRecordScale(c, m, CriticalSearch{0.0, 5.0, 0.01, 1e-6});
        QCOMPARE(RecordSamples::constructed() - before, 1L);
        QVERIFY(r.runs > 10);
        QVERIFY(r.peak);

        const auto samples = std::make_shared<const RecordSamples>(m, c.tstar);
        const double unit = std::abs(m.peak().value);
        for (const double peak : {0.61, 0.8, *r.peak, *r.peak - 1e-6, 1.3, 4.9}) {
            const SlabResult whole = solveExact(RecordedMotion(m, c.tstar, peak), c.slab);
            const SlabResult view = runRecord1D(c, samples, peak);
            QCOMPARE(view.outcome, whole.outcome);
            QVERIFY(sameBits(view.tauC, whole.tauC)); // QCOMPARE of doubles is fuzzy
            QVERIFY(sameBits(view.tauEnd, whole.tauEnd));
            QVERIFY(sameBits(view.maxAbsDelta, whole.maxAbsDelta));
            QVERIFY(sameBits(view.residualDelta, whole.residualDelta));
            QCOMPARE(view.slipIntervals, whole.slipIntervals);
            // The view's samples are the old motion's: each sample times peak / unscaled peak.
            const RecordedMotion v(samples, peak);
            const std::vector<double> a = v.samples();
            const double s = peak / unit;
            for (std::size_t k = 0; k < a.size(); ++k)
                QVERIFY(sameBits(a[k], m.samples[k] * s));
            double maxAbs = 0.0;
            for (const double x : a)
                maxAbs = std::max(maxAbs, std::abs(x));
            QVERIFY(sameBits(v.peak(), maxAbs));
        }
    }
    void verdictsAgainstTheCodes() {
        // Two ratios either side of a critical peak of 0.8 g: the sine's rule (ch. V).
        RecordCriticalScale crit;
        crit.peak = 0.8;
        CodeResult low, high;
        low.code = "ubc1976";
        low.topRatio = 0.14;
        low.periodSeconds = 1.0;
        high.code = "atc306";
        high.topRatio = 0.9;
        high.periodSeconds = 1.0;
        const auto v = recordVerdicts({low, high}, crit, CriticalSearch{});
        QCOMPARE(v.size(), std::size_t(2));
        QVERIFY(v[0].verdict == Verdict::OverstressGoverns);
        QCOMPARE(*v[0].margin, 0.8 / 0.14);
        QVERIFY(v[1].verdict == Verdict::KineticInstabilityGoverns);
        QVERIFY(QString::fromStdString(v[0].explanation).contains("critical record peak = 0.8 g"));
    }
};

QTEST_APPLESS_MAIN(TestRecordCritical)
#include "tst_record_critical.moc"
