// SPDX-License-Identifier: GPL-3.0-or-later
// The Records and Numerics tabs of the main window (docs/theory.md §7, §6.6): a record loads or is
// refused with its reason; the work-precision study plots one curve per case and solver and
// cancels.

#include "ui/FrictionPanel.h"
#include "ui/MainWindow.h"
#include "ui/NumericsView.h"
#include "ui/RecordPreview.h"
#include "ui/RecordsTab.h"

#include <QTabWidget>
#include <QTemporaryDir>
#include <QtTest>

using namespace kinstab;
using namespace kinstab::ui;

class TestToolTabs : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }
    // On its own the tab shows no record until one is opened (issue 30: it showed RSN68 UP
    // through a horizontal floor filter for every project).
    void recordsTabStartsEmpty() {
        RecordsTab tab;
        QVERIFY(!tab.preview()->record().has_value());
        QVERIFY(tab.messageText().contains("No record"));
        QVERIFY(tab.open(KINSTAB_SOURCE_DIR "/resources/records/RSN68_SFERN_PEL-UP.AT2"));
        QVERIFY(tab.preview()->record()->samples.size() >
                1000); // RSN68 UP has 3,000 samples (SOURCES.md)
    }
    void brokenRecordIsRefusedWithItsReason() {
        RecordsTab tab;
        QTemporaryDir dir;
        const QString path = dir.filePath("broken.AT2");
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("PEER NGA STRONG MOTION DATABASE RECORD\nheader\nACCELERATION IN UNITS OF G\n"
                "NPTS=   10, DT=   .0100 SEC\n0.1 0.2 abc\n");
        f.close();
        QVERIFY(!tab.open(path));
        QVERIFY(!tab.errorText().isEmpty());
        QVERIFY(!tab.open(dir.filePath("missing.AT2")));
        QVERIFY(tab.errorText().contains("missing.AT2"));
    }
    void numericsPlotsOneCurvePerCaseAndSolver() {
        NumericsView view;
        WorkPrecisionStudy study;
        auto row = [](const char* c, const char* s, double e, double t) {
            WorkPrecisionRow r;
            r.caseId = c;
            r.solver = s;
            r.error = e;
            r.timing.minSeconds = t;
            return r;
        };
        study.rows = {
            row("paper-1Hz", "paper", 3.7e-2, 1.2e-4), row("paper-1Hz", "paper", 4.6e-4, 2.9e-2),
            row("paper-1Hz", "exact", 4.4e-15, 1.0e-4), row("grazing", "exact", 0.0, 3e-6)};
        view.showStudy(study);
        QCOMPARE(view.curveCount(), 3);
    }
    void numericsStudyCancels() {
        NumericsView view;
        QSignalSpy shown(&view, &NumericsView::studyShown);
        view.startStudy();
        QVERIFY(view.isRunning());
        view.cancelStudy();
        QTRY_VERIFY_WITH_TIMEOUT(!view.isRunning(), 60000);
        QCOMPARE(shown.count(), 0); // a cancelled study shows nothing half-done
    }
    void mainWindowHasTheTabs() {
        MainWindow w;
        auto* tabs = w.findChild<QTabWidget*>();
        QVERIFY(tabs);
        QStringList names;
        for (int i = 0; i < tabs->count(); ++i)
            names << tabs->tabText(i);
        QVERIFY(names.contains("Records"));
        QVERIFY(names.contains("Numerics"));
        QVERIFY(names.contains("Friction"));
        // KINSTAB_SCREENSHOT_DIR=docs/screenshots regenerates the README's pictures of these tabs.
        const QString dir = qEnvironmentVariable("KINSTAB_SCREENSHOT_DIR");
        if (dir.isEmpty()) return;
        w.resize(1280, 800);
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        for (const char* name : {"Records", "Friction"}) {
            tabs->setCurrentIndex(names.indexOf(name));
            QTest::qWait(200);
            QVERIFY(w.grab().save(dir + "/gui-" + QString(name).toLower() + ".png"));
        }
    }
    void frictionMuReachesTheSlab() {
        MainWindow w;
        auto* panel = w.findChild<FrictionPanel*>();
        QVERIFY(panel);
        emit panel->useMu(0.55); // the paper's bed-joint mu_inf (ch. III)
        QCOMPARE(w.currentCase().slab.mu, 0.55);
    }
};

QTEST_MAIN(TestToolTabs)
#include "tst_tool_tabs.moc"
