// SPDX-License-Identifier: GPL-3.0-or-later
// Screenshots of the free-standing block (issue 32) at 1280 × 800: the overturning map of Zhang &
// Makris (2001)'s block under the one-sine pulse (linearised, restitution 0.9, the exact
// equations' boundary dashed over it; the safe cape shows), and the Teaching tab's block
// animation mid-rock. Written to $KINSTAB_SCREENSHOT_DIR when set (docs/screenshots/ holds the
// committed ones; taken under xvfb-run with QT_QPA_PLATFORM=xcb), else to a temporary folder;
// the test checks the window shows what it claims.

#include "ui/BlockMapView.h"
#include "ui/MainWindow.h"
#include "ui/ModelPanel.h"
#include "ui/OverturningMapPlot.h"
#include "ui/teaching/BlockTeachingView.h"
#include "ui/teaching/TeachingPlayer.h"

#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QImage>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QtTest>

using namespace kinstab;
using namespace kinstab::ui;

class TestBlockScreenshots : public QObject {
    Q_OBJECT
private:
    QTemporaryDir tmp_;
    QString dir() const {
        const QString env = qEnvironmentVariable("KINSTAB_SCREENSHOT_DIR");
        return env.isEmpty() ? tmp_.path() : env;
    }
    void shoot(MainWindow& w, const QString& name) {
        const QString path = QDir(dir()).filePath(name);
        QVERIFY(w.screenshot().save(path));
        QCOMPARE(QImage(path).size(), w.size());
    }
    static void showTab(MainWindow& w, const QString& title) {
        auto* tabs = w.findChild<QTabWidget*>();
        for (int i = 0; i < tabs->count(); ++i)
            if (tabs->tabText(i) == title) tabs->setCurrentIndex(i);
    }

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }

    void overturningMap() {
        MainWindow w;
        w.resize(1280, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        // Zhang & Makris 2001: p = 2.14 rad/s, alpha = 0.25, eta = 0.9, linearised, one-sine.
        Project p = w.project();
        p.units = UnitSystem::SI;
        p.blockMap.selected = true;
        p.blockMap.block = blockFromAlphaP(0.25, 2.14);
        p.blockMap.restitution = 0.9;
        p.blockMap.equations = RockingEquations::Linearised;
        p.blockMap.shape = PulseShape::OneSine;
        p.blockMap.points = 100; // steps of 0.1: 4.5, 5.0, 7.0, 9.0 are points
        w.showProject(p);
        QVERIFY(w.modelPanel()->isBlock());
        QSignalSpy done(&w, &MainWindow::blockMapFinished);
        w.runSweep();
        QVERIFY(done.wait(300000));
        const auto& r = w.blockMapView()->result();
        QVERIFY(r.has_value());
        // The safe cape at omega_p/p = 5 (Zhang & Makris 2001; tests/core/tst_rocking_pulses):
        // 4.5 alpha g overturns, 7.0 survives, 9.0 overturns. Points k = 1..100 of 10 / 100.
        const auto at = [&](double w5, double a) {
            const int i = static_cast<int>(std::lround(w5 * 10.0)) - 1;
            const int j = static_cast<int>(std::lround(a * 10.0)) - 1;
            return int(r->main.overturns[r->main.at(i, j)]);
        };
        QCOMPARE(at(5.0, 4.5), 1);
        QCOMPARE(at(5.0, 7.0), 0);
        QCOMPARE(at(5.0, 9.0), 1);
        // A point read out as the user hovers it.
        OverturningMapPlot* plot = w.blockMapView()->plot();
        const QRectF pr = plot->plotRect();
        QTest::mouseMove(plot, QPoint(static_cast<int>(pr.left() + pr.width() * 0.5),
                                      static_cast<int>(pr.bottom() - pr.height() * 0.7)));
        QTRY_VERIFY(!w.blockMapView()->readoutText().isEmpty());
        for (QDockWidget* d : w.findChildren<QDockWidget*>()) // the block's inputs in view
            if (d->windowTitle() == QStringLiteral("Model")) d->raise();
        QTest::qWait(600);
        shoot(w, QStringLiteral("gui-block-map-1280x800.png"));
    }

    void teachingAnimation() {
        MainWindow w;
        w.resize(1280, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        showTab(w, QStringLiteral("Teaching"));
        w.teachingSubject()->setCurrentIndex(1);
        BlockTeachingView* v = w.blockTeachingView();
        QVERIFY(v->applyPreset(QStringLiteral("zhang-makris-overturns")));
        // After the impact, on its way over the other corner.
        const auto& impacts = v->run().result().impactTimes;
        QVERIFY(!impacts.empty() && v->run().result().overturnTime);
        const double t1 = impacts.front(), t2 = *v->run().result().overturnTime;
        v->player()->seek(t1 + 0.7 * (t2 - t1));
        QVERIFY(std::abs(v->displayedState().theta) > 0.5 * v->run().alpha());
        // The window fits itself to the screen a moment after its first show (MainWindow::
        // showEvent): the image after that, as the app's own screenshots are taken.
        QTest::qWait(600);
        shoot(w, QStringLiteral("gui-teaching-block-1280x800.png"));
    }
};

QTEST_MAIN(TestBlockScreenshots)
#include "tst_block_screenshots.moc"
