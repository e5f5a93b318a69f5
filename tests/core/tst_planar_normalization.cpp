// SPDX-License-Identifier: GPL-3.0-or-later
// The two S_max normalizations of the planar model (docs/theory.md §5) and the side a slab leaves
// by.
//  - product (default, ch. IV): each component peaks at its amplitude;
//  - envelope (as printed in ch. VI): each peaks at A max(e sin) / max(e).
// Both peaks are checked against an independent fine sampling of the paper's formula.
// docs/theory.md §5: with the default, gravity only, f_y = 0.2 Hz and f_x = 2 Hz the slab leaves
// along the walls from A_x = 0.85 (the paper reports no such collapse).

#include "core/slab/PlanarCase.h"

#include <QtTest>

#include <cmath>
#include <numbers>

using namespace kinstab;

class TestPlanarNormalization : public QObject {
    Q_OBJECT
private slots:
    void componentPeaks_data();
    void componentPeaks();
    void alongWallExit_data();
    void alongWallExit();
};

namespace {
// max over tau of |e(t* tau) sin(omega tau)| and max of e, by sampling (step 1e-3 in tau, to tau =
// 400: ten times the envelope's peak).
void sampledMaxima(const Envelope& env, double f, double tstar, double& product, double& envelope) {
    const double w = 2.0 * std::numbers::pi * f * tstar;
    product = envelope = 0.0;
    for (long i = 1; i < 400'000; ++i) {
        const double tau = 1e-3 * static_cast<double>(i);
        const double e = std::exp(-env.alpha * tstar * tau) - std::exp(-env.beta * tstar * tau);
        product = std::max(product, std::abs(e * std::sin(w * tau)));
        envelope = std::max(envelope, e);
    }
}
double peakOfAx(const SlabModel2D& m) {
    double peak = 0.0;
    for (long i = 1; i < 400'000; ++i)
        peak = std::max(peak, std::abs(m.accel(1e-3 * i).x));
    return peak;
}
} // namespace

void TestPlanarNormalization::componentPeaks_data() {
    QTest::addColumn<double>("f");
    QTest::newRow("f 0.5 Hz (Fig. 37-42 grid)") << 0.5;
    QTest::newRow("f 2 Hz (Fig. 37-42 grid)") << 2.0;
}

void TestPlanarNormalization::componentPeaks() {
    QFETCH(double, f);
    PlanarCase c;
    double product = 0, envelope = 0;
    sampledMaxima(c.common.envelope, f, c.common.tstar, product, envelope);
    const double a = 0.8;
    QVERIFY(std::abs(peakOfAx(planarModel(c, a, f)) - a) < 1e-6);
    c.normalization = PlanarNormalization::Envelope;
    const double expected = a * product / envelope;
    QVERIFY(expected < a);
    QVERIFY(std::abs(peakOfAx(planarModel(c, a, f)) - expected) < 1e-6);
}

void TestPlanarNormalization::alongWallExit_data() {
    QTest::addColumn<int>("normalization");
    QTest::newRow("product (default)") << int(PlanarNormalization::Product);
    QTest::newRow("envelope (ch. VI print)") << int(PlanarNormalization::Envelope);
}

void TestPlanarNormalization::alongWallExit() {
    QFETCH(int, normalization);
    PlanarCase c;
    c.fyHz = 0.2;
    c.normalization = static_cast<PlanarNormalization>(normalization);
    const PlanarResult below = runPlanar(c, 0.80, 2.0);
    QCOMPARE(below.slab.outcome, Outcome::Stable);
    QVERIFY(below.maxAbsDeltaY < c.theta);
    for (double ax : {0.85, 1.0, 1.15}) {
        const PlanarResult r = runPlanar(c, ax, 2.0);
        QCOMPARE(r.slab.outcome, Outcome::Collapsed);
        QCOMPARE(r.exitSide, ExitSide::Along);
        QVERIFY(std::abs(std::abs(r.residualDeltaY) - c.theta) < 1e-9);
        QVERIFY(std::abs(r.slab.residualDelta) <= c.common.slab.limit);
    }
}

QTEST_APPLESS_MAIN(TestPlanarNormalization)
#include "tst_planar_normalization.moc"
