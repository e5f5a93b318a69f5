// SPDX-License-Identifier: GPL-3.0-or-later
// The Teaching tab's free-standing block (issue 32), offscreen: each preset of a published case
// loads and its run ends as its paper says; after a scrub the drawn state is core's recorded
// path at that time (the reference: simulateRocking run here with its own recorder, read by its
// own linear interpolation); the tab switches between the slab and the block.

#include "core/base/PhysicalConstants.h"
#include "core/rocking/RockingSolver.h"
#include "ui/MainWindow.h"
#include "ui/teaching/BlockPresets.h"
#include "ui/teaching/BlockTeachingView.h"
#include "ui/teaching/TeachingPlayer.h"
#include "ui/teaching/TeachingView.h"

#include <QComboBox>
#include <QSettings>
#include <QSlider>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTest>

#include <cmath>

using namespace kinstab;
using namespace kinstab::ui;

class TestBlockTeaching : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    void presetsEndAsPublished_data() {
        QTest::addColumn<QString>("id");
        QTest::addColumn<int>("outcome");
        // Housner 1963: free rocking from theta0 = alpha/2 loses energy at each impact and stops.
        QTest::newRow("housner-free") << "housner-free" << int(RockingOutcome::Rocks);
        // Makris & Roussos 2000 worked example: 5.44 m/s^2 (above eq. 27's 5.439) overturns.
        QTest::newRow("makris-roussos") << "makris-roussos" << int(RockingOutcome::Overturns);
        // Zhang & Makris 2001: 4.5 alpha g overturns (first interval 3.02-6.32 alpha g), 7.0
        // survives (the safe cape, 6.33-7.17).
        QTest::newRow("zhang-makris-overturns")
            << "zhang-makris-overturns" << int(RockingOutcome::Overturns);
        QTest::newRow("zhang-makris-cape") << "zhang-makris-cape" << int(RockingOutcome::Rocks);
        // Housner 1963 eq. 9: 2 % longer than the critical duration overturns.
        QTest::newRow("housner-rectangular")
            << "housner-rectangular" << int(RockingOutcome::Overturns);
        // Shenton 1996: mu = 0.3 < tan alpha = 1 and 0.6 g < g tan alpha: it slides, never rocks.
        QTest::newRow("squat-slides") << "squat-slides" << int(RockingOutcome::Slides);
    }
    void presetsEndAsPublished() {
        QFETCH(QString, id);
        QFETCH(int, outcome);
        BlockTeachingView v;
        QVERIFY(v.applyPreset(id));
        QCOMPARE(v.currentPresetId(), id);
        QCOMPARE(v.run().error(), std::string());
        QCOMPARE(int(v.run().result().outcome), outcome);
        QVERIFY(v.run().path().samples.size() > 10);
        if (outcome == int(RockingOutcome::Overturns)) {
            // The end of the animation shows it lying on its side.
            v.player()->seek(v.run().end());
            const RockingSample last = v.displayedState();
            QVERIFY2(std::abs(std::abs(last.theta) - std::numbers::pi / 2) < 1e-6,
                     qPrintable(QStringLiteral("t %1 theta %2 over %3 samples %4 end %5")
                                    .arg(last.t)
                                    .arg(last.theta)
                                    .arg(v.run().result().overturnTime.value_or(-1))
                                    .arg(v.run().path().samples.back().t)
                                    .arg(v.run().result().endTime)));
        }
        QVERIFY(!v.applyPreset(QStringLiteral("no-such-case")));
    }

    void housnerFirstImpact() {
        // Housner 1963 (exact equations here, so only near the linearised 1/p acosh 2): the
        // event list's first impact is the solver's.
        BlockTeachingView v;
        QVERIFY(v.applyPreset(QStringLiteral("housner-free")));
        QVERIFY(!v.run().result().impactTimes.empty());
        v.player()->stepToNextEvent();
        QCOMPARE(v.player()->tau(), v.run().eventTimes().front());
        QCOMPARE(v.run().eventTimes().front(), v.run().result().impactTimes.front());
        QCOMPARE_LE(std::abs(v.displayedState().theta), 1e-9); // at an impact theta = 0
    }

    void scrubShowsCorePath_data() {
        QTest::addColumn<QString>("id");
        QTest::addColumn<int>("scrub");
        QTest::newRow("makris-roussos") << "makris-roussos" << 4321;
        QTest::newRow("zhang-makris-cape") << "zhang-makris-cape" << 2500;
        QTest::newRow("squat-slides") << "squat-slides" << 7000;
    }
    void scrubShowsCorePath() {
        QFETCH(QString, id);
        QFETCH(int, scrub);
        BlockTeachingView v;
        v.resize(1000, 600);
        QVERIFY(v.applyPreset(id));
        v.scrubber()->setValue(scrub);
        const double t = v.player()->tau();
        QCOMPARE_LE(std::abs(t - v.run().end() * scrub / BlockTeachingView::kScrubSteps), 1e-12);
        // The reference: core's run of the same case recorded here.
        const BlockCase& c = findBlockPreset(id)->blockCase;
        std::vector<RockingSample> path;
        RockingRunOptions o;
        o.sampleInterval = kBlockSampleInterval;
        o.recorder = [&path](const RockingSample& s) { path.push_back(s); };
        simulateRocking(c.model, PulseMotion(*c.pulse), o);
        std::size_t k = 0;
        while (k + 1 < path.size() && path[k + 1].t <= t)
            ++k;
        QVERIFY(k + 1 < path.size());
        const RockingSample& a = path[k];
        const RockingSample& b = path[k + 1];
        const double u = (t - a.t) / (b.t - a.t);
        const RockingSample shown = v.displayedState();
        QCOMPARE(shown.t, t);
        QCOMPARE_LE(std::abs(shown.theta - (a.theta + u * (b.theta - a.theta))), 1e-12);
        QCOMPARE_LE(std::abs(shown.sliding - (a.sliding + u * (b.sliding - a.sliding))), 1e-12);
        QCOMPARE(shown.mode, a.mode);
        // Something moves at that time: the comparison is not of two zeros.
        QVERIFY(std::abs(shown.theta) + std::abs(shown.sliding) > 1e-6);
    }

    void tabSwitchesToTheBlock() {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto* stack = w.blockTeachingView()->parentWidget();
        QVERIFY(stack->isAncestorOf(w.teachingView()));
        QCOMPARE(w.teachingSubject()->currentIndex(), 0);
        QVERIFY(w.teachingView()->isVisibleTo(stack));
        QVERIFY(!w.blockTeachingView()->isVisibleTo(stack));
        // The choice shows in the tab bar's corner only while Teaching is the tab shown.
        auto* tabs = w.findChild<QTabWidget*>();
        tabs->setCurrentIndex(0);
        QVERIFY(!w.teachingSubject()->isVisible());
        for (int i = 0; i < tabs->count(); ++i)
            if (tabs->tabText(i) == QStringLiteral("Teaching")) tabs->setCurrentIndex(i);
        QVERIFY(w.teachingSubject()->isVisible());
        w.teachingSubject()->setCurrentIndex(1);
        QVERIFY(!w.teachingView()->isVisibleTo(stack));
        QVERIFY(w.blockTeachingView()->isVisibleTo(stack));
    }
};

QTEST_MAIN(TestBlockTeaching)
#include "tst_block_teaching.moc"
