// SPDX-License-Identifier: GPL-3.0-or-later
// core/numerics/HalleyRoot.h: the safeguarded Halley iteration of the exact solver's root solves
// (docs/theory.md §6.3) against known roots, its evaluation count against Newton's, and its
// Newton mode (third derivative not known) against safeguardedNewton bit for bit.

#include "core/numerics/HalleyRoot.h"

#include <QtTest>
#include <cmath>

using namespace kinstab;

namespace {
// The Dottie number, the root of cos x = x (OEIS A003957: 0.73908513321516064165...).
constexpr double kDottie = 0.7390851332151606416;

struct CosMinusX {
    int* calls;
    void operator()(double x, Derivatives& d) const {
        ++*calls;
        d = {std::cos(x) - x, -std::sin(x) - 1.0, -std::cos(x), std::sin(x)};
    }
};
} // namespace

class TestHalleyRoot : public QObject {
    Q_OBJECT
private slots:
    // From 1e-3 off, Halley's error goes 1e-3 -> ~1e-10 -> below an ulp, and the third derivative
    // says so after the second evaluation; Newton (1e-3 -> 1e-7 -> 1e-14 -> ulp) needs three.
    void cubicFromNearStart() {
        int halley = 0, newton = 0;
        const RootResult h = safeguardedHalley(CosMinusX{&halley}, 0.0, 1.0, 1.0,
                                               std::cos(1.0) - 1.0, 200, kDottie + 1e-3);
        const RootResult n = safeguardedNewton(
            [&](double x, double& f, double& df) {
                ++newton;
                f = std::cos(x) - x;
                df = -std::sin(x) - 1.0;
            },
            0.0, 1.0, 1.0, std::cos(1.0) - 1.0, 200, kDottie + 1e-3);
        QVERIFY(h.converged);
        QCOMPARE_LE(std::abs(h.x - kDottie), 4.0 * std::numeric_limits<double>::epsilon());
        QCOMPARE_LE(std::abs(n.x - kDottie), 4.0 * std::numeric_limits<double>::epsilon());
        QCOMPARE_EQ(halley, 2);
        QCOMPARE_GT(newton, halley);
    }
    // A start 1e-6 off: one evaluation, and the predicted error (about 1e-18) ends the solve.
    void oneEvaluationFromCloseStart() {
        int calls = 0;
        const RootResult h = safeguardedHalley(CosMinusX{&calls}, 0.0, 1.0, 1.0,
                                               std::cos(1.0) - 1.0, 200, kDottie - 1e-6);
        QCOMPARE_EQ(calls, 1);
        QCOMPARE_LE(std::abs(h.x - kDottie), 4.0 * std::numeric_limits<double>::epsilon());
    }
    // Without the third derivative (d3f NaN, d2f 0) every step is Newton's: the same iterate and
    // the same count as safeguardedNewton, from a bad start (bisection steps) too.
    void newtonModeIsNewton() {
        // x^3 + 4 x^2 - 10 on [1, 2] (Burden & Faires' example, root 1.36523...).
        for (const double start : {1.05, 1.5, 1.95}) {
            int h = 0, n = 0;
            const auto f = [](double x) { return x * x * x + 4.0 * x * x - 10.0; };
            const auto df = [](double x) { return 3.0 * x * x + 8.0 * x; };
            const RootResult a = safeguardedHalley(
                [&](double x, Derivatives& d) {
                    ++h;
                    d.f = f(x);
                    d.df = df(x);
                },
                1.0, 2.0, f(1.0), f(2.0), 200, start);
            const RootResult b = safeguardedNewton(
                [&](double x, double& fx, double& dfx) {
                    ++n;
                    fx = f(x);
                    dfx = df(x);
                },
                1.0, 2.0, f(1.0), f(2.0), 200, start);
            QVERIFY(a.converged);
            QCOMPARE_EQ(a.x, b.x);
            QCOMPARE_EQ(h, n);
        }
    }
    // Steps that would leave the bracket are not taken: a root near an end, f flat far from it.
    void staysInBracket() {
        int calls = 0;
        const RootResult r = safeguardedHalley(
            [&](double x, Derivatives& d) {
                ++calls;
                d = {std::atan(x - 0.999), 1.0 / (1.0 + (x - 0.999) * (x - 0.999)),
                     -2.0 * (x - 0.999) / std::pow(1.0 + (x - 0.999) * (x - 0.999), 2.0), 0.0};
                const double u = x - 0.999, w = 1.0 + u * u;
                d.d3f = (6.0 * u * u - 2.0) / (w * w * w);
            },
            -20.0, 1.0, std::atan(-20.999), std::atan(0.001), 200, -19.0);
        QVERIFY(r.converged);
        QCOMPARE_LE(std::abs(r.x - 0.999), 1e-15);
        QCOMPARE_LE(calls, 60);
    }
};

QTEST_APPLESS_MAIN(TestHalleyRoot)
#include "tst_halley_root.moc"
