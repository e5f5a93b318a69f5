// SPDX-License-Identifier: GPL-3.0-or-later
// The Floors view: the example project (paper building, Pacoima Dam 164) runs off the GUI
// thread and shows the PFA profile (model, SDOF roof point, three code demands), the critical
// PGA of all 16 levels and a picked level's motion with the slab's run; a bad record path is
// a message, not a crash; the main window has the tab. KINSTAB_FLOORS_SHOT=FILE.png saves a
// screenshot of the view.

#include "core/io/Project.h"
#include "ui/FloorsView.h"
#include "ui/MainWindow.h"

#include <QChartView>
#include <QSignalSpy>
#include <QTabWidget>
#include <QXYSeries>
#include <QtTest>

using namespace kinstab;

namespace {
Project floorsProject() {
    return loadProject(KINSTAB_SOURCE_DIR "/resources/examples/paper-16-story-floors.json");
}
} // namespace

class TestFloorsView : public QObject {
    Q_OBJECT
private slots:
    void runsAndShowsTheProfile();
    void badRecordIsAMessage();
    void mainWindowHasTheTab();
};

void TestFloorsView::runsAndShowsTheProfile() {
    const Project p = floorsProject();
    ui::FloorsView view([p] { return p; });
    view.resize(1280, 900);
    view.show(); // applies the project's record and floors settings
    view.setRecordPath(":/records/RSN77_SFERN_PUL164.AT2"); // the same record, shipped
    QSignalSpy shown(&view, &ui::FloorsView::analysisShown);
    view.run();
    QVERIFY(view.isRunning() || shown.count() == 1);
    QVERIFY(shown.count() == 1 || shown.wait(60000));
    const auto profile = view.profileView()->chart()->series();
    QCOMPARE(profile.size(), 5); // model, ASCE design, ASCE MCE_R, EC8, SDOF roof
    QCOMPARE(static_cast<QXYSeries*>(profile[0])->count(), 17); // the base and 16 levels
    const auto critical = view.criticalView()->chart()->series();
    QCOMPARE(static_cast<QXYSeries*>(critical[0])->count(), 16);
    QVERIFY(view.message().startsWith("Level 16:")); // the slab's level is picked first
    view.pickLevel(8);
    QVERIFY(view.message().startsWith("Level 8:"));
    QCOMPARE(view.levelView()->chart()->series().size(), 3); // ground, level, slab
    if (qEnvironmentVariableIsSet("KINSTAB_FLOORS_SHOT")) {
        view.pickLevel(16);
        QTest::qWait(200);
        QVERIFY(view.grab().save(qEnvironmentVariable("KINSTAB_FLOORS_SHOT")));
    }
}

void TestFloorsView::badRecordIsAMessage() {
    const Project p = floorsProject();
    ui::FloorsView view([p] { return p; });
    view.setRecordPath("/nonexistent/record.at2");
    view.run();
    QVERIFY(!view.isRunning());
    QVERIFY(view.message().contains("Cannot read the record"));
    QVERIFY(view.message().contains("/nonexistent/record.at2"));
}

void TestFloorsView::mainWindowHasTheTab() {
    ui::MainWindow w;
    auto* tabs = qobject_cast<QTabWidget*>(w.centralWidget());
    QVERIFY(tabs);
    bool found = false;
    for (int i = 0; i < tabs->count(); ++i)
        found = found || tabs->tabText(i) == "Floors";
    QVERIFY(found);
}

QTEST_MAIN(TestFloorsView)
#include "tst_floors_view.moc"
