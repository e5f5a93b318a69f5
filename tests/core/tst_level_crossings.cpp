// SPDX-License-Identifier: GPL-3.0-or-later
// core/numerics/LevelCrossings.h: all sign changes of a function on an interval, found on
// sub-intervals, and the scan that starts at `from` (the planar solver's onset scan from where the
// slab sticks). f(t) = sin(3 t) - 0.5 on [0, 10] crosses zero where 3 t = pi/6 + 2 pi k or
// 5 pi/6 + 2 pi k (the closed form, the reference for the roots); f(t) = 0.2 - (t - 1.3)^2 on
// [0, 2] has both its roots t = 1.3 -+ sqrt(0.2) inside one sub-interval, found through its
// extremum. A scan from `from` must report, bit for bit, every root of the whole scan that lies
// in a sub-interval ending after `from`.

#include "core/numerics/LevelCrossings.h"

#include <QtTest>

#include <cmath>
#include <cstring>
#include <numbers>
#include <vector>

using namespace kinstab;

namespace {
bool sameBits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

void sine(double t, double& f, double& df) {
    f = std::sin(3.0 * t) - 0.5;
    df = 3.0 * std::cos(3.0 * t);
}

std::vector<double> scan(double lo, double hi, int sub, double from = -INFINITY) {
    std::vector<double> out;
    CrossingScanWork work;
    levelCrossings(sine, lo, hi, sub, out, work, from);
    return out;
}
} // namespace

class TestLevelCrossings : public QObject {
    Q_OBJECT
private slots:
    void findsEveryRoot() {
        const std::vector<double> roots = scan(0.0, 10.0, 40);
        std::vector<double> exact;
        for (int k = 0; k < 5; ++k)
            for (double base : {std::numbers::pi / 6.0, 5.0 * std::numbers::pi / 6.0}) {
                const double t = (base + 2.0 * std::numbers::pi * k) / 3.0;
                if (t <= 10.0) exact.push_back(t);
            }
        QCOMPARE(roots.size(), exact.size());
        for (std::size_t i = 0; i < roots.size(); ++i)
            QCOMPARE_LE(std::abs(roots[i] - exact[i]), 1e-13);
    }

    void aScanFromATimeKeepsTheWholeScansRoots() {
        const int sub = 16; // 0.625 wide, below the half-period pi/3 of sin(3 t): one extremum
        const std::vector<double> whole = scan(0.0, 10.0, sub);
        QCOMPARE(whole.size(), std::size_t{10}); // the closed form's ten roots in [0, 10]
        for (double from : {0.0, 0.7, 1.25, 3.3, 5.0, 9.99}) {
            const std::vector<double> part = scan(0.0, 10.0, sub, from);
            // The sub-interval holding `from` is scanned whole: its start is the first kept.
            const double width = 10.0 / sub, start = std::floor(from / width) * width;
            std::vector<double> expected;
            for (double r : whole)
                if (r > start) expected.push_back(r);
            QCOMPARE(part.size(), expected.size());
            for (std::size_t i = 0; i < part.size(); ++i)
                QVERIFY(sameBits(part[i], expected[i]));
        }
    }

    void twoRootsInOneSubInterval() {
        std::vector<double> out;
        CrossingScanWork work;
        levelCrossings(
            [](double t, double& f, double& df) {
                f = 0.2 - (t - 1.3) * (t - 1.3);
                df = -2.0 * (t - 1.3);
            },
            0.0, 2.0, 1, out, work);
        QCOMPARE(out.size(), std::size_t{2});
        QCOMPARE_LE(std::abs(out[0] - (1.3 - std::sqrt(0.2))), 1e-13);
        QCOMPARE_LE(std::abs(out[1] - (1.3 + std::sqrt(0.2))), 1e-13);
    }
};

QTEST_APPLESS_MAIN(TestLevelCrossings)
#include "tst_level_crossings.moc"
