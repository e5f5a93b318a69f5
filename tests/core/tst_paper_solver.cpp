// SPDX-License-Identifier: GPL-3.0-or-later
// The 1980 RK4 baseline (Appendix) against the exact solver on the paper's grid
// (A 0.70..1.15 by 0.05, f 0.5..1.125 by 0.125, three envelopes): it converges as H shrinks
// and agrees on every outcome at H = T/1024.

#include "core/slab/Slab1DCase.h"
#include "core/sweep/Grid.h"

#include <QtTest>
#include <cmath>
#include <map>

using namespace kinstab;

namespace {

struct GridError {
    double maxTauError = 0; // over points where both collapse
    int outcomeMismatches = 0;
    int failures = 0;
};

GridError compareOnPaperGrid(EnvelopePreset preset, double stepsPerPeriod) {
    Slab1DCase exact;
    exact.envelope = Envelope::fromPreset(preset);
    Slab1DCase paper = exact;
    paper.solver = SolverKind::Paper;
    paper.paperStepsPerPeriod = stepsPerPeriod;
    GridError e;
    for (double A : linspaceStep(0.70, 1.15, 0.05))
        for (double f : linspaceStep(0.5, 1.125, 0.125)) {
            const SlabResult x = runSlab1D(exact, A, f);
            const SlabResult p = runSlab1D(paper, A, f);
            if (p.outcome == Outcome::Failed) ++e.failures;
            if (x.outcome != p.outcome)
                ++e.outcomeMismatches;
            else if (x.outcome == Outcome::Collapsed)
                e.maxTauError = std::max(e.maxTauError, std::abs(x.tauC - p.tauC));
        }
    return e;
}

} // namespace

class TestPaperSolver : public QObject {
    Q_OBJECT
private slots:
    void paperGridMatchesItsOwnChecks() {
        // The paper's solver at its own step H = T/16 reproduces the paper's statement:
        // moderate, f = 1 Hz: A = 0.95 stable, A = 1.00 collapses.
        Slab1DCase c;
        c.solver = SolverKind::Paper;
        QCOMPARE(runSlab1D(c, 0.95, 1.0).outcome, Outcome::Stable);
        QCOMPARE(runSlab1D(c, 1.00, 1.0).outcome, Outcome::Collapsed);
    }
    void convergesToExact_data() {
        QTest::addColumn<int>("preset");
        QTest::newRow("fast") << int(EnvelopePreset::Fast);
        QTest::newRow("moderate") << int(EnvelopePreset::Moderate);
        QTest::newRow("slow") << int(EnvelopePreset::Slow);
    }
    void convergesToExact() {
        QFETCH(int, preset);
        std::map<int, GridError> errors;
        for (int n : {16, 32, 64, 128, 256, 512, 1024})
            errors[n] = compareOnPaperGrid(EnvelopePreset(preset), n);
        QString table;
        for (const auto& [n, e] : errors)
            table += QString("  H=T/%1: max|dtau_c|=%2 outcome mismatches=%3 failures=%4\n")
                         .arg(n)
                         .arg(e.maxTauError, 0, 'g', 3)
                         .arg(e.outcomeMismatches)
                         .arg(e.failures);
        // The paper's collapse time is the end of the step in which |delta| > 1 (Appendix), so
        // tau_c converges at first order: the error falls about 4x from T/64 to T/256 and 4x again
        // to T/1024. Observed order over T/64..T/1024 from the max error:
        const double order = std::log2(errors[64].maxTauError / errors[1024].maxTauError) / 4.0;
        qInfo().noquote() << "paper vs exact:\n" << table << "  observed order" << order;
        QCOMPARE(errors[1024].outcomeMismatches, 0);
        QCOMPARE(errors[1024].failures, 0);
        // Within one step of the coarsest grid frequency (f = 0.5 Hz: T = 1/(0.5 t*) in tau).
        QCOMPARE_LE(errors[1024].maxTauError, (1.0 / (0.5 * 0.099)) / 1024);
        QCOMPARE_GE(order, 0.8);
        QCOMPARE_LE(errors[1024].maxTauError, errors[64].maxTauError);
    }
};

QTEST_APPLESS_MAIN(TestPaperSolver)
#include "tst_paper_solver.moc"
