// SPDX-License-Identifier: GPL-3.0-or-later
// Genuinely two-dimensional runs of the planar solver against two independent references:
//  - Moreau's proximal implicit Euler (docs/theory.md §6.5), first order, at steps h and h/2 with
//    Richardson extrapolation (no event location at all, so it shares no logic with the solver);
//  - the solver itself at a much tighter tolerance (self-convergence).
// And lift-off: a vertical motion that reaches -1 g ends the run at the first n = 0, which is
// found here independently from the enveloped sine's own crossing brackets.

#include "core/excitation/EnvelopedSine.h"
#include "core/slab/MoreauSolver2D.h"
#include "core/slab/PlanarCase.h"

#include <QtTest>

#include <cmath>

using namespace kinstab;

class TestPlanarReference : public QObject {
    Q_OBJECT
private slots:
    void agreesWithMoreau_data();
    void agreesWithMoreau();
    void liftOffIsReported();
};

void TestPlanarReference::agreesWithMoreau_data() {
    QTest::addColumn<double>("ax");
    QTest::addColumn<double>("fx");
    QTest::addColumn<double>("fy");
    QTest::addColumn<double>("az"); // amplitude of an enveloped-sine vertical (3 Hz), 0: none
    QTest::addColumn<int>("side");
    QTest::newRow("ch. VI default, A_x 1.0, f_x 1, f_y 0.5") << 1.0 << 1.0 << 0.5 << 0.0 << 1;
    QTest::newRow("A_x 0.9, f_x 0.75, f_y 2") << 0.9 << 0.75 << 2.0 << 0.0 << 1;
    QTest::newRow("A_x 0.9, f_x 1, f_y 1.25, vertical 0.4 g at 3 Hz")
        << 0.9 << 1.0 << 1.25 << 0.4 << 1;
    QTest::newRow("docs/theory.md §5 along-wall exit, A_x 0.9, f_x 2, f_y 0.2")
        << 0.9 << 2.0 << 0.2 << 0.0 << 2;
}

void TestPlanarReference::agreesWithMoreau() {
    QFETCH(double, ax);
    QFETCH(double, fx);
    QFETCH(double, fy);
    QFETCH(double, az);
    QFETCH(int, side);
    PlanarCase c;
    c.fyHz = fy;
    if (az > 0.0)
        c.vertical = std::make_shared<EnvelopedSine>(c.common.envelope, az, 3.0, c.common.tstar);
    const PlanarResult p = runPlanar(c, ax, fx);
    PlanarCase tight = c;
    tight.solver.relTol = 1e-13;
    tight.solver.absTol = 1e-15;
    const PlanarResult q = runPlanar(tight, ax, fx);
    const SlabModel2D model = planarModel(c, ax, fx);
    const double horizon = 2.0 * p.slab.tauC;
    const PlanarResult m1 = solveMoreau2D(model, 2e-3, horizon);
    const PlanarResult m2 = solveMoreau2D(model, 1e-3, horizon);
    QCOMPARE(p.slab.outcome, Outcome::Collapsed);
    QCOMPARE(int(p.exitSide), side);
    QCOMPARE(q.exitSide, p.exitSide);
    QCOMPARE(m2.exitSide, p.exitSide);
    const double ref = richardsonFirstOrder(m1.slab.tauC, m2.slab.tauC);
    qInfo("tau_c: solver %.12g, tight %.12g, Moreau h=2e-3 %.9g, h=1e-3 %.9g, Richardson %.9g",
          p.slab.tauC, q.slab.tauC, m1.slab.tauC, m2.slab.tauC, ref);
    qInfo("work: %ld steps, %ld rejected, %ld evaluations, %ld events", p.slab.work.steps,
          p.slab.work.restarts, p.slab.work.accelEvaluations, p.slab.work.events);
    // Measured: default vs tight tolerance within 1e-11, Richardson within 1e-7 (its own error
    // is O(h^2); the two Moreau runs differ by 2e-5).
    QVERIFY(std::abs(p.slab.tauC - q.slab.tauC) < 1e-9 * q.slab.tauC);
    QVERIFY(std::abs(p.slab.tauC - ref) < 1e-6 * ref);
}

void TestPlanarReference::liftOffIsReported() {
    PlanarCase c;
    c.fyHz = 0.5;
    auto vertical = std::make_shared<EnvelopedSine>(c.common.envelope, 1.2, 3.0, c.common.tstar);
    c.vertical = vertical;
    // First tau where a_z falls through -1: from the sine's own per-half-period brackets.
    double expected = NAN;
    for (double t = 0.0; std::isnan(expected);) {
        const double end = vertical->segmentEnd(t);
        const Crossings cr = vertical->crossings(-1.0, t, end);
        if (cr.n > 0) expected = cr.t[0];
        t = end;
    }
    const PlanarResult p = runPlanar(c, 0.5, 1.0);
    QCOMPARE(p.slab.outcome, Outcome::LiftOff);
    QVERIFY(std::abs(p.tauLiftOff - expected) < 1e-10 * expected);
    QCOMPARE(p.slab.tauC, p.tauLiftOff);
}

QTEST_APPLESS_MAIN(TestPlanarReference)
#include "tst_planar_reference.moc"
