// SPDX-License-Identifier: GPL-3.0-or-later
// With A_y = 0 and no vertical motion the planar model is the 1-DOF model (docs/theory.md §5; the
// paper checks this in ch. VI): its collapse time must agree with the closed-form event-driven
// 1-DOF solver to 1e-8 relative over the paper's grid (A 0.70:1.15:0.05, f 0.5:1.125:0.125) for the
// three envelope presets.

#include "core/slab/PlanarCase.h"
#include "core/slab/Slab1DCase.h"

#include <QtTest>

#include <cmath>

using namespace kinstab;

class TestPlanarOneDof : public QObject {
    Q_OBJECT
private slots:
    void agreesWithExactSolver_data();
    void agreesWithExactSolver();
};

void TestPlanarOneDof::agreesWithExactSolver_data() {
    QTest::addColumn<int>("preset");
    QTest::newRow("paper grid, fast envelope (Fig. 28 grid)") << int(EnvelopePreset::Fast);
    QTest::newRow("paper grid, moderate envelope (Fig. 29 grid)") << int(EnvelopePreset::Moderate);
    QTest::newRow("paper grid, slow envelope (Fig. 30 grid)") << int(EnvelopePreset::Slow);
}

void TestPlanarOneDof::agreesWithExactSolver() {
    QFETCH(int, preset);
    Slab1DCase one;
    one.envelope = Envelope::fromPreset(static_cast<EnvelopePreset>(preset));
    PlanarCase planar;
    planar.common.envelope = one.envelope;
    planar.ayRatio = 0.0;
    int collapsed = 0, compared = 0;
    double worst = 0.0;
    for (int i = 0; i <= 9; ++i) {
        const double a = 0.70 + 0.05 * i;
        for (int j = 0; j <= 5; ++j) {
            const double f = 0.5 + 0.125 * j;
            const SlabResult exact = runSlab1D(one, a, f);
            const PlanarResult p = runPlanar(planar, a, f);
            const QString where = QString("A = %1, f = %2").arg(a).arg(f);
            QVERIFY2(p.slab.outcome == exact.outcome,
                     qPrintable(where + ": outcome " +
                                QString::fromStdString(outcomeName(p.slab.outcome)) + " vs exact " +
                                QString::fromStdString(outcomeName(exact.outcome))));
            QCOMPARE(p.slab.slipIntervals, exact.slipIntervals);
            ++compared;
            if (exact.outcome != Outcome::Collapsed) continue;
            ++collapsed;
            QCOMPARE(p.exitSide, ExitSide::Across);
            const double rel = std::abs(p.slab.tauC - exact.tauC) / exact.tauC;
            worst = std::max(worst, rel);
            QVERIFY2(rel < 1e-8, qPrintable(where + QString(": tau_c %1 vs exact %2, rel %3")
                                                        .arg(p.slab.tauC, 0, 'g', 15)
                                                        .arg(exact.tauC, 0, 'g', 15)
                                                        .arg(rel)));
        }
    }
    QVERIFY(collapsed > 0); // the grid straddles A_crit, so both outcomes are exercised
    QVERIFY(collapsed < compared);
    qInfo("worst relative tau_c difference: %.3g over %d collapses", worst, collapsed);
}

QTEST_APPLESS_MAIN(TestPlanarOneDof)
#include "tst_planar_onedof.moc"
