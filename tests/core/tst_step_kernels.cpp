// SPDX-License-Identifier: GPL-3.0-or-later
// The planar solver's two step kernels that promise the same bits as their plain forms:
//  - dop853Step<N, First, Count> forms only the stage components the right-hand side reads; on
//    the planar slip (which reads u, not the displacement) its results equal the full form's bit
//    for bit, over a run of steps;
//  - SmallLu (core/numerics/SmallLinearSolve.h) solves a 5x5 system that needs row exchanges to
//    the solution it was built from, reuses its elimination for a second right-hand side, and
//    refuses a singular matrix.

#include "core/numerics/Dop853.h"
#include "core/numerics/SmallLinearSolve.h"
#include "core/slab/PlanarCase.h"

#include "SlipRhs.h"

#include <QtTest>

#include <cmath>

using namespace kinstab;

namespace {

using testing::slipRhs;

using Vec4 = OdeVec<4>;
using Vec5 = Eigen::Matrix<double, 5, 1>;

// A matrix whose first column's largest entry is in the last row and whose (1,1) entry is 0, so
// that the elimination must exchange rows; regular (its determinant is far from 0).
SmallLu<5>::Rows pivotingMatrix() {
    return {{{0.0, 2.0, -1.0, 0.5, 1.0},
             {1.0, -3.0, 2.0, 0.0, 4.0},
             {-2.0, 1.0, 0.0, 3.0, -1.0},
             {0.5, 0.0, 5.0, -2.0, 2.0},
             {7.0, 1.0, -1.0, 1.0, 0.0}}};
}

Vec5 times(const SmallLu<5>::Rows& a, const Vec5& x) {
    Vec5 b = Vec5::Zero();
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j)
            b[i] += a[i][j] * x[j];
    return b;
}

} // namespace

class TestStepKernels : public QObject {
    Q_OBJECT
private slots:
    void dop853ReadsOnlyWhatTheRightHandSideReads() {
        PlanarCase c;
        c.fyHz = 1.0;
        const SlabModel2D m = planarModel(c, 0.9, 1.0);
        auto f = [&](double t, const Vec4& y) { return slipRhs(m, t, y); };
        Vec4 y;
        y << 0.1, -0.2, 0.3, -0.05;
        double t = 5.0;
        const double h = 0.02;
        for (int i = 0; i < 50; ++i, t += h) {
            const Vec4 f0 = f(t, y);
            const auto full = dop853Step<4>(f, t, y, f0, h);
            const auto partial = dop853Step<4, 2, 2>(f, t, y, f0, h);
            for (int k = 0; k < 4; ++k) {
                QCOMPARE(partial.y[k], full.y[k]); // exact: the same operations on u
                QCOMPARE(partial.f[k], full.f[k]);
                QCOMPARE(partial.err5[k], full.err5[k]);
                QCOMPARE(partial.err3[k], full.err3[k]);
            }
            y = full.y;
        }
        QVERIFY(std::abs(y[0] - 0.1) > 1e-3); // the steps went somewhere
    }

    void smallLuSolvesWithRowExchanges() {
        const SmallLu<5>::Rows a = pivotingMatrix();
        SmallLu<5> lu;
        QVERIFY(lu.factor(a));
        // x chosen, b = A x formed independently: the solve must return x to rounding.
        Vec5 x1, x2;
        x1 << 1.0, -2.0, 0.5, 3.0, -1.5;
        x2 << -0.25, 4.0, 1.0, -3.0, 2.0;
        Vec5 b1 = times(a, x1), b2 = times(a, x2);
        lu.solve(b1);
        lu.solve(b2); // the same elimination, a second right-hand side
        for (int i = 0; i < 5; ++i) {
            QVERIFY(std::abs(b1[i] - x1[i]) < 1e-13);
            QVERIFY(std::abs(b2[i] - x2[i]) < 1e-13);
        }
    }

    void smallLuRefusesASingularMatrix() {
        SmallLu<5>::Rows a = pivotingMatrix();
        a[3] = a[1]; // two equal rows
        SmallLu<5> lu;
        QVERIFY(!lu.factor(a));
    }
};

QTEST_APPLESS_MAIN(TestStepKernels)
#include "tst_step_kernels.moc"
