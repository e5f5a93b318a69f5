// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab::nextAfter is std::nextafter bit for bit: the reference is std::nextafter itself, over
// the edge cases of the encoding (zeros, subnormals, the largest double, infinities, NaN) and
// random doubles of every exponent, toward values above, below and equal.
#include "core/base/NextAfter.h"

#include <QtTest>

#include <bit>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

using kinstab::nextAfter;

class TestNextAfter : public QObject {
    Q_OBJECT
private slots:
    void matchesLibm();
};

namespace {
bool sameBits(double a, double b) {
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}
} // namespace

void TestNextAfter::matchesLibm() {
    using L = std::numeric_limits<double>;
    std::vector<double> xs = {
        0.0,      -0.0,      L::denorm_min(), -L::denorm_min(), L::min(),       -L::min(),
        L::max(), -L::max(), L::infinity(),   -L::infinity(),   L::quiet_NaN(), 1.0,
        -1.0,     0.1,       303.030303030303};
    std::mt19937_64 rng(7);
    std::uniform_int_distribution<std::uint64_t> bits;
    for (int i = 0; i < 20000; ++i)
        xs.push_back(std::bit_cast<double>(bits(rng)));
    int checked = 0;
    for (double x : xs) {
        for (double toward : {x, -x, 0.0, -0.0, 2.0 * x, 0.5 * x, L::infinity(), -L::infinity(),
                              L::quiet_NaN(), 1.0, -1.0}) {
            QVERIFY2(sameBits(nextAfter(x, toward), std::nextafter(x, toward)),
                     qPrintable(QString::number(x, 'g', 17) + " toward " +
                                QString::number(toward, 'g', 17)));
            ++checked;
        }
    }
    QCOMPARE(checked, 11 * 20015);
}

QTEST_APPLESS_MAIN(TestNextAfter)
#include "tst_next_after.moc"
