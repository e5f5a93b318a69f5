// SPDX-License-Identifier: GPL-3.0-or-later
// ui/TimeLeft and the status bar's RunProgress (issue #18): the time-left estimate is exact for a
// steady rate, moves only a little when one poll sees no progress, and a new run never shows the
// previous run's text.

#include "ui/RunProgress.h"
#include "ui/TimeLeft.h"

#include <QtTest>

using namespace kinstab::ui;

class TestTimeLeft : public QObject {
    Q_OBJECT

private slots:
    void steadyRateGivesTheExactTimeLeft() {
        // 100 units/s, polled every 0.25 s: after t s, 100 t of 1000 are done, 10 - t s are left
        // (hand calculation).
        TimeLeft t;
        QVERIFY(!t.secondsLeft()); // nothing yet
        for (int k = 1; k <= 20; ++k) {
            const double s = 0.25 * k;
            t.update(s, static_cast<std::size_t>(100 * s), 1000);
            if (s < TimeLeft::warmUpSeconds) {
                QVERIFY(!t.secondsLeft()); // not during the first second
                continue;
            }
            QVERIFY(t.secondsLeft());
            QCOMPARE_LE(std::abs(*t.secondsLeft() - (10.0 - s)), 1e-9);
            QCOMPARE_LE(std::abs(t.rate() - 100.0), 1e-9);
        }
    }

    void oneStalledPollMovesItLittle() {
        TimeLeft t;
        for (int k = 1; k <= 12; ++k)
            t.update(0.25 * k, static_cast<std::size_t>(25 * k), 1000); // 100/s for 3 s
        const double before = *t.secondsLeft();                         // 700 left at 100/s: 7 s
        t.update(3.25, 300, 1000);                                      // a poll with no progress
        // The smoothed rate drops by the weight 1 - exp(-0.25/3) = 8.0 %, so the estimate rises
        // by 1/(1 - 0.080) - 1 = 8.7 % (hand calculation); the last-interval rate would be 0,
        // an infinite time left.
        const double after = *t.secondsLeft();
        QCOMPARE_LE(std::abs(before - 7.0), 1e-9);
        QCOMPARE_LE(std::abs(after / before - 1.0 / std::exp(-0.25 / 3.0)), 1e-9);
        QVERIFY(after / before < 1.1);
    }

    void runProgressStartsClean() {
        RunProgress bar;
        bar.start(400, QStringLiteral("steps"));
        bar.update(399, 400);
        bar.finish();
        bar.start(40401, QStringLiteral("steps"));
        QVERIFY(bar.format().startsWith(QStringLiteral("0 / ")));
        QVERIFY(bar.format().endsWith(QStringLiteral(" steps")));
        QVERIFY(!bar.format().contains(QStringLiteral("399")));
        QCOMPARE(bar.value(), 0);
    }

    void timeLeftTextUsesWholeUnits() {
        QCOMPARE(timeLeftText(44.6), QStringLiteral("about 45 s left"));
        QCOMPARE(timeLeftText(185), QStringLiteral("about 3 min left"));
        QCOMPARE(timeLeftText(4800), QStringLiteral("about 1 h 20 min left"));
    }
};

QTEST_MAIN(TestTimeLeft)
#include "tst_time_left.moc"
