// SPDX-License-Identifier: GPL-3.0-or-later
// The Teaching view in a lecture hall (issue #18): presentation mode (F11 full screen with the
// docks hidden and the text scaled, Esc back to the window as it was), slow motion by default,
// keys that work after a click on the scene, preset titles whose outcome is the run's, and a
// play bar that stays on screen at 1280 × 800 with the planar preset.

#include "ui/MainWindow.h"
#include "ui/teaching/FigurePresets.h"
#include "ui/teaching/PresentationMode.h"
#include "ui/teaching/SlabAnimation.h"
#include "ui/teaching/TeachingPlayer.h"
#include "ui/teaching/TeachingView.h"

#include <QAction>
#include <QApplication>
#include <QComboBox>
#include <QDockWidget>
#include <QMenuBar>
#include <QStandardPaths>
#include <QToolButton>
#include <QtTest>

using namespace kinstab;
using namespace kinstab::ui;

namespace {
QList<QDockWidget*> visibleDocks(MainWindow& w) {
    QList<QDockWidget*> out;
    for (QDockWidget* d : w.findChildren<QDockWidget*>())
        if (d->isVisible()) out << d;
    return out;
}
// The window at 1280 × 800 with the Teaching tab in front.
bool showTeachingTab(MainWindow& w) {
    w.resize(1280, 800);
    w.show();
    auto* tabs = w.findChild<QTabWidget*>();
    for (int i = 0; i < tabs->count(); ++i)
        if (tabs->widget(i)->isAncestorOf(w.teachingView())) tabs->setCurrentIndex(i);
    return QTest::qWaitForWindowExposed(&w);
}
} // namespace

class TestTeachingPresentation : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void f11EntersAndEscLeaves() {
        MainWindow w;
        w.resize(1280, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        const int docksBefore = static_cast<int>(visibleDocks(w).size());
        QVERIFY(docksBefore > 0);
        auto* mode = w.findChild<PresentationMode*>(QStringLiteral("presentationMode"));
        QVERIFY(mode);
        QTest::keyClick(&w, Qt::Key_F11);
        QVERIFY(mode->isActive());
        QVERIFY(w.windowState() & Qt::WindowFullScreen);
        QVERIFY(visibleDocks(w).isEmpty());
        QVERIFY(!w.menuBar()->isVisible());
        QVERIFY(w.teachingView()->isVisible());
        // The text scale applied to the view's widgets: twice the application's font.
        TeachingView* view = w.teachingView();
        QCOMPARE(view->fontScale(), PresentationMode::kDefaultScale);
        QCOMPARE(view->font().pointSizeF(),
                 QApplication::font().pointSizeF() * PresentationMode::kDefaultScale);
        auto* box = view->findChild<QComboBox*>(QStringLiteral("fontScale"));
        QVERIFY(box);
        QCOMPARE(box->currentData().toDouble(), PresentationMode::kDefaultScale);
        // Esc leaves even with the focus on the scene.
        view->animation()->setFocus();
        QTest::keyClick(view->animation(), Qt::Key_Escape);
        QVERIFY(!mode->isActive());
        QVERIFY(!(w.windowState() & Qt::WindowFullScreen));
        QTRY_COMPARE(static_cast<int>(visibleDocks(w).size()), docksBefore);
        QVERIFY(w.menuBar()->isVisible());
        QCOMPARE(view->fontScale(), 1.0);
    }

    void fontScaleControlIsRemembered() {
        MainWindow w;
        w.show();
        auto* mode = w.findChild<PresentationMode*>(QStringLiteral("presentationMode"));
        mode->enter();
        w.teachingView()->setFontScale(3.0);
        mode->leave();
        QCOMPARE(w.teachingView()->fontScale(), 1.0);
        mode->enter();
        QCOMPARE(w.teachingView()->fontScale(), 3.0);
        mode->leave();
        w.teachingView()->setFontScale(PresentationMode::kDefaultScale); // for the next test
        mode->enter();
        w.teachingView()->setFontScale(PresentationMode::kDefaultScale);
        mode->leave();
    }

    void slowMotionIsTheDefault() {
        TeachingView view;
        QVERIFY(view.player()->speed() < 1.0);
        QCOMPARE(view.player()->speed(), TeachingPlayer::kDefaultSpeed);
    }

    void keysWorkAfterClickingTheScene() {
        MainWindow w;
        QVERIFY(showTeachingTab(w));
        TeachingView* view = w.teachingView();
        QTRY_VERIFY(view->animation()->isVisible());
        QTest::mouseClick(view->animation(), Qt::LeftButton);
        QCOMPARE(QApplication::focusWidget(), view->animation());
        TeachingPlayer* player = view->player();
        QVERIFY(!player->isPlaying());
        QTest::keyClick(view->animation(), Qt::Key_Space);
        QVERIFY(player->isPlaying());
        QTest::keyClick(view->animation(), Qt::Key_Space);
        QVERIFY(!player->isPlaying());
        const double tau = player->tau();
        QTest::keyClick(view->animation(), Qt::Key_Right);
        QVERIFY(player->tau() > tau);
        QTest::keyClick(view->animation(), Qt::Key_Left);
        QCOMPARE_LE(std::abs(player->tau() - tau), 1e-9);
    }

    // A title that names an outcome must be the outcome of the run it shows.
    void presetTitlesTellTheOutcome() {
        TeachingView view;
        for (const FigurePreset& p : figurePresets()) {
            QVERIFY(view.applyPreset(p.id));
            const Outcome o = view.run().result().outcome;
            QVERIFY2(!p.title.contains(QStringLiteral("Fig.")), qPrintable(p.title));
            QVERIFY2(!p.figure.isEmpty(), qPrintable(p.id));
            if (p.title.contains(QStringLiteral("walks off")))
                QVERIFY2(o == Outcome::Collapsed, qPrintable(p.title));
            if (p.title.contains(QStringLiteral("stays")))
                QVERIFY2(o == Outcome::Stable, qPrintable(p.title));
        }
    }

    // At 1280 × 800 the play button stays inside the window with every preset.
    void playBarStaysOnScreen() {
        MainWindow w;
        QVERIFY(showTeachingTab(w));
        TeachingView* view = w.teachingView();
        QToolButton* play = nullptr;
        for (QToolButton* b : view->findChildren<QToolButton*>())
            if (b->toolTip().startsWith(QStringLiteral("Play"))) play = b;
        QVERIFY(play);
        for (const QString& id : {QStringLiteral("fig29"), QStringLiteral("fig39")}) {
            view->applyPreset(id);
            QTest::qWait(50);
            const QRect inWindow(play->mapTo(&w, QPoint(0, 0)), play->size());
            QVERIFY2(w.rect().contains(inWindow) && !play->visibleRegion().isEmpty(),
                     qPrintable(id));
        }
    }
};

QTEST_MAIN(TestTeachingPresentation)
#include "tst_teaching_presentation.moc"
