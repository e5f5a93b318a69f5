// SPDX-License-Identifier: GPL-3.0-or-later
// Stress suite, range of the inputs (docs/theory.md §6.6; docs/theory.md §6.6 cases 8, 10, 11, 12,
// 13 and the metamorphic tests): f from 0.01 to 100 Hz, A up to 100 g, alpha close to beta, against
// the independent quadrature reference; a -> -a, amplitude scaling and time scaling, which need no
// reference at all.

#include "QuadratureReference.h"
#include "StressHelpers.h"
#include "core/excitation/EnvelopedSine.h"
#include "core/slab/ExactSolver.h"

#include <QtTest>
#include <algorithm>
#include <cmath>
#include <numbers>

using namespace kinstab;
using testing::checkDefined;

namespace {
struct Case {
    Envelope envelope;
    double A, f, mu, limit;
};

// Against the independent quadrature reference (tests/core/QuadratureReference.h). Its event
// times come from bisection to 1e-15 relative: an error dt there moves the velocity by at most
// (A + mu) dt and the displacement, over a slip no longer than a half-period pi / omega, by
// (A + mu) dt pi / omega. The flow is non-expansive (docs/theory.md §6.1 F5), so these add up over
// the slips: that sum (or 1e-9 relative) bounds the residual difference.
void compareWithReference(const Case& c, const SlabResult& r) {
    const EnvelopedSine a(c.envelope, c.A, c.f, 0.099);
    const double period = 2.0 * std::numbers::pi / a.omega();
    testing::QuadratureReference ref(a, c.mu, c.limit, std::min(period / 64.0, 0.5));
    const testing::ReferenceResult want = ref.run(1e5);
    QCOMPARE(outcomeName(r.outcome), outcomeName(want.outcome));
    QCOMPARE(r.slipIntervals, want.slipIntervals);
    if (want.outcome == Outcome::Collapsed) {
        QCOMPARE_LE(std::abs(r.tauC / want.tauC - 1.0), 1e-9);
        return;
    }
    const double perSlip =
        (c.A + c.mu) * 1e-15 * std::max(1.0, r.tauEnd) * std::numbers::pi / a.omega();
    const double budget = std::max(1e-9 * std::abs(want.residualDelta), r.slipIntervals * perSlip);
    QCOMPARE_LE(std::abs(r.residualDelta - want.residualDelta), budget);
}

SlabResult solve(const Case& c, double tstar = 0.099) {
    const EnvelopedSine a(c.envelope, c.A, c.f, tstar);
    SlabParams p;
    p.mu = c.mu;
    p.limit = c.limit;
    return solveExact(a, p);
}

const Envelope kModerate = Envelope::fromPreset(EnvelopePreset::Moderate);
const Envelope kFast = Envelope::fromPreset(EnvelopePreset::Fast);
} // namespace

class TestStressRange : public QObject {
    Q_OBJECT
private slots:
    // f from 0.01 Hz (the whole record inside one half-period) to 100 Hz (thousands of
    // half-periods; NUMERICS §4 rows 10, 11) and A up to 100 g (row 8).
    void frequencyAndAmplitude_data() {
        QTest::addColumn<double>("A");
        QTest::addColumn<double>("f");
        QTest::addColumn<double>("limit");
        for (double f : {0.01, 0.1, 1.0, 10.0, 100.0})
            for (double A : {1.0, 5.0}) {
                const QByteArray n = "A=" + QByteArray::number(A) + " f=" + QByteArray::number(f);
                QTest::newRow(n.constData()) << A << f << 1.0;
            }
        QTest::newRow("A=100 f=20 (NUMERICS §4 row 8)") << 100.0 << 20.0 << 1.0;
        QTest::newRow("A=100 f=100 (NUMERICS §4 row 8)") << 100.0 << 100.0 << 1.0;
        QTest::newRow("A=100 f=1 no collapse (NUMERICS §4 row 8)") << 100.0 << 1.0 << 1e5;
    }
    void frequencyAndAmplitude() {
        QFETCH(double, A);
        QFETCH(double, f);
        QFETCH(double, limit);
        const Case c{kModerate, A, f, 0.6, limit};
        const SlabResult r = solve(c);
        checkDefined(r);
        compareWithReference(c, r);
    }

    // alpha close to beta (NUMERICS §4 row 12): A / S_max ~ 1 / (beta - alpha) is huge and
    // the closed-form integrals must not subtract the two exponentials. The reference
    // integrates a(tau) by quadrature, so it shares nothing with the closed forms.
    void alphaNearBeta_data() {
        QTest::addColumn<double>("relGap");
        QTest::addColumn<double>("A");
        for (double gap : {1e-3, 1e-6, 1e-10, 1e-14})
            for (double A : {0.9, 1.2}) {
                const QByteArray n =
                    "beta=alpha(1+" + QByteArray::number(gap) + ") A=" + QByteArray::number(A);
                QTest::newRow(n.constData()) << gap << A;
            }
    }
    void alphaNearBeta() {
        QFETCH(double, relGap);
        QFETCH(double, A);
        const Case c{Envelope{0.15, 0.15 * (1.0 + relGap), std::nullopt}, A, 1.0, 0.6, 1.0};
        const SlabResult r = solve(c);
        checkDefined(r);
        compareWithReference(c, r);
    }

    // As beta -> alpha the normalised motion tends to the limit shape t e^{-alpha t} sin:
    // the answers converge (a model difference of O(beta - alpha)), they do not wander.
    void alphaNearBetaConverges() {
        const auto at = [](double gap) {
            return solve(
                Case{Envelope{0.15, 0.15 * (1.0 + gap), std::nullopt}, 1.2, 1.0, 0.6, 1.0});
        };
        const SlabResult a = at(1e-8), b = at(1e-12), c = at(1e-15);
        QCOMPARE(outcomeName(a.outcome), std::string("collapsed"));
        QCOMPARE_LE(std::abs(a.tauC / b.tauC - 1.0), 1e-7);
        QCOMPARE_LE(std::abs(b.tauC / c.tauC - 1.0), 1e-10);
    }

    // a -> -a gives delta -> -delta (NUMERICS §4, metamorphic): same outcome, tau_c and slips.
    void mirror_data() {
        QTest::addColumn<double>("A");
        QTest::addColumn<double>("f");
        QTest::addColumn<int>("preset");
        QTest::newRow("moderate A=1 f=1 (collapse)") << 1.0 << 1.0 << 1;
        QTest::newRow("moderate A=0.9 f=1 (stable)") << 0.9 << 1.0 << 1;
        QTest::newRow("fast A=0.62 f=10 (chattering)") << 0.62 << 10.0 << 0;
        QTest::newRow("moderate A=100 f=20 (reversals)") << 100.0 << 20.0 << 1;
    }
    void mirror() {
        QFETCH(double, A);
        QFETCH(double, f);
        QFETCH(int, preset);
        const EnvelopedSine a(Envelope::fromPreset(EnvelopePreset(preset)), A, f, 0.099);
        const testing::NegatedExcitation minus(a);
        SlabParams p;
        const SlabResult r = solveExact(a, p), m = solveExact(minus, p);
        checkDefined(r);
        checkDefined(m);
        QCOMPARE(outcomeName(m.outcome), outcomeName(r.outcome));
        QCOMPARE(m.slipIntervals, r.slipIntervals);
        QCOMPARE(m.work.events, r.work.events);
        if (r.outcome == Outcome::Collapsed) QCOMPARE(m.tauC, r.tauC);
        QCOMPARE_LE(std::abs(m.residualDelta + r.residualDelta),
                    1e-13 * std::max(1.0, std::abs(r.residualDelta)));
    }

    // Scaling a and mu by lambda scales delta by lambda (NUMERICS §4 row 8): with the limit
    // scaled too, tau_c and the slip count are unchanged. A = 100 g, mu = 60 is lambda = 100.
    void amplitudeScaling_data() {
        QTest::addColumn<double>("A");
        QTest::addColumn<double>("f");
        QTest::addColumn<double>("lambda");
        QTest::newRow("A=1 f=1 x10") << 1.0 << 1.0 << 10.0;
        QTest::newRow("A=1 f=1 x100 (A=100 g)") << 1.0 << 1.0 << 100.0;
        QTest::newRow("A=0.9 f=2 x100 (A=90 g, stable)") << 0.9 << 2.0 << 100.0;
        QTest::newRow("A=1.3 f=0.5 x0.01") << 1.3 << 0.5 << 0.01;
    }
    void amplitudeScaling() {
        QFETCH(double, A);
        QFETCH(double, f);
        QFETCH(double, lambda);
        const SlabResult base = solve({kModerate, A, f, 0.6, 1.0});
        const SlabResult scaled = solve({kModerate, A * lambda, f, 0.6 * lambda, lambda});
        checkDefined(base);
        checkDefined(scaled);
        QCOMPARE(outcomeName(scaled.outcome), outcomeName(base.outcome));
        QCOMPARE(scaled.slipIntervals, base.slipIntervals);
        if (base.outcome == Outcome::Collapsed)
            QCOMPARE_LE(std::abs(scaled.tauC / base.tauC - 1.0), 1e-12);
        QCOMPARE_LE(std::abs(scaled.residualDelta / lambda - base.residualDelta),
                    1e-12 * std::max(1.0, std::abs(base.residualDelta)));
    }

    // Time scaling (NUMERICS §4, metamorphic): t* -> kappa t* scales alpha t*, beta t* and
    // omega by kappa, so a(tau) -> a(kappa tau), delta(tau) -> delta(kappa tau) / kappa^2.
    // With the limit divided by kappa^2, tau_c is divided by kappa.
    void timeScaling_data() {
        QTest::addColumn<double>("kappa");
        QTest::newRow("kappa=4") << 4.0;
        QTest::newRow("kappa=0.1") << 0.1;
        QTest::newRow("kappa=37") << 37.0;
    }
    void timeScaling() {
        QFETCH(double, kappa);
        const Case c{kFast, 1.1, 1.0, 0.6, 1.0};
        const SlabResult base = solve(c);
        Case s = c;
        s.limit = 1.0 / (kappa * kappa);
        const SlabResult scaled = solve(s, 0.099 * kappa);
        checkDefined(base);
        checkDefined(scaled);
        QCOMPARE(outcomeName(base.outcome), std::string("collapsed"));
        QCOMPARE(outcomeName(scaled.outcome), outcomeName(base.outcome));
        QCOMPARE(scaled.slipIntervals, base.slipIntervals);
        QCOMPARE_LE(std::abs(scaled.tauC * kappa / base.tauC - 1.0), 1e-11);
    }
};

QTEST_APPLESS_MAIN(TestStressRange)
#include "tst_stress_range.moc"
