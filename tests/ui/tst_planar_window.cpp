// SPDX-License-Identifier: GPL-3.0-or-later
// The main window's model switch (docs/user-guide.md "model (1-DOF / planar)", issue #7),
// offscreen: the planar fields appear only with the planar model and gate Run there; a planar sweep
// shows what runPlanar computes for each point (independent calls, the vertical record read from
// the source tree rather than the Qt resource); its A_crit and verdict come from the planar model;
// picking shows the planar history; the project keeps the settings; a cancel stops the sweep.

#include "WindowFields.h"
#include "core/io/Project.h"
#include "core/records/RecordReader.h"
#include "core/sweep/CriticalAmplitude.h"
#include "ui/GridPanel.h"
#include "ui/MainWindow.h"
#include "ui/ModelPanel.h"
#include "ui/NumberField.h"
#include "ui/PlanarHistoryChart.h"
#include "ui/SurfaceView.h"
#include "ui/VerdictPanel.h"
#include "ui/teaching/TeachingView.h"

#include <QAction>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <memory>

using namespace kinstab;
using namespace kinstab::ui;

class TestPlanarWindow : public QObject {
    Q_OBJECT
private:
    std::unique_ptr<MainWindow> w;
    NumberField* field(const char* name) { return testing::namedField(w.get(), name); }
    QComboBox* modelCombo() {
        return w->modelPanel()->findChild<QComboBox*>(QStringLiteral("model"));
    }
    void setText(const char* name, const QString& text) {
        QLineEdit* e = field(name)->lineEdit();
        e->selectAll();
        QTest::keyClicks(e, text); // typed, as a user would
    }
    bool waitFinished(int ms) {
        QSignalSpy spy(w.get(), &MainWindow::sweepFinished);
        return spy.count() > 0 || spy.wait(ms);
    }
    // The case the window should run, built without the GUI: the record file from the source
    // tree (resources/records, byte-identical to the shipped resource), core's planarCaseFrom.
    static PlanarCase independentCase(const Project& p) {
        std::shared_ptr<const Excitation1D> vertical;
        if (p.planar.vertical == VerticalSource::Rsn68Up)
            vertical = verticalMotion(
                readRecord(KINSTAB_SOURCE_DIR "/resources/records/RSN68_SFERN_PEL-UP.AT2"),
                p.slab.tstar);
        return planarCaseFrom(p.slab, p.planar, vertical);
    }

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear(); // a first start: the paper's example, 1-DOF
    }
    void init() {
        w = std::make_unique<MainWindow>();
        w->show();
        QVERIFY(QTest::qWaitForWindowExposed(w.get()));
    }
    void cleanup() { w.reset(); }

    void switchShowsPlanarFields() {
        QVERIFY(w->project().model == ModelKind::Slab1D);
        for (const char* f : {"fy", "ayRatio", "theta"})
            QVERIFY2(!field(f)->isVisibleTo(w.get()), f);
        modelCombo()->setCurrentIndex(1);
        for (const char* f : {"fy", "ayRatio", "theta"})
            QVERIFY2(field(f)->isVisibleTo(w.get()), f);
        QVERIFY(w->project().model == ModelKind::Planar);
        QVERIFY(w->windowTitle().contains(QStringLiteral("planar")));
        modelCombo()->setCurrentIndex(0);
        QVERIFY(!field("fy")->isVisibleTo(w.get()));
    }

    void badFyShowsMessageAndDisablesRun() {
        modelCombo()->setCurrentIndex(1);
        QVERIFY(w->runAction()->isEnabled());
        setText("fy", "-1");
        QVERIFY(!field("fy")->isValid());
        // The message is beside the field, in the field's own widget.
        const auto labels = field("fy")->findChildren<QLabel*>();
        bool shown = false;
        for (QLabel* l : labels)
            shown |= l->isVisibleTo(w.get()) && l->text() == field("fy")->error();
        QVERIFY2(shown, qPrintable(field("fy")->error()));
        QVERIFY(!w->runAction()->isEnabled());
        QVERIFY(w->runAction()->toolTip().contains(QStringLiteral("f_y")));
        // A hidden planar field does not gate the 1-DOF model.
        modelCombo()->setCurrentIndex(0);
        QVERIFY(w->runAction()->isEnabled());
    }

    void brokenVerticalFileDisablesRun() {
        modelCombo()->setCurrentIndex(1);
        w->modelPanel()
            ->findChild<QComboBox*>(QStringLiteral("verticalSource"))
            ->setCurrentIndex(2);              // record file
        QVERIFY(!w->runAction()->isEnabled()); // no file named yet
        QLineEdit* path = w->modelPanel()->verticalPathEdit();
        path->setText(QStringLiteral("/nonexistent/UP.AT2"));
        emit path->editingFinished();
        QVERIFY(w->modelPanel()->verticalError().contains(QStringLiteral("/nonexistent/UP.AT2")));
        QVERIFY(!w->runAction()->isEnabled());
        path->setText(
            QStringLiteral(KINSTAB_SOURCE_DIR "/resources/records/RSN68_SFERN_PEL-UP.AT2"));
        emit path->editingFinished();
        QCOMPARE(w->modelPanel()->verticalError(), QString());
        QVERIFY(w->runAction()->isEnabled());
    }

    // 3 x 2 grid around the planar critical region of the paper's slab (mu 0.6, t* 0.099 s,
    // moderate envelope), with the default RSN68 UP vertical.
    void smallPlanarSweepMatchesRunPlanar() {
        modelCombo()->setCurrentIndex(1);
        w->gridPanel()->setRanges(GridRanges{0.6, 1.0, 0.2, 1.0, 2.0, 1.0});
        w->runAction()->trigger();
        QVERIFY(waitFinished(300000));
        QVERIFY(w->sweepPlanarCase().has_value());
        const Project p = w->project();
        const PlanarCase c = independentCase(p);
        const SweepResult& r = w->lastSweep();
        QCOMPARE(r.completed, std::size_t(6));
        const GammaGrid& shown = w->surfaceView()->data();
        QVERIFY(shown.gammaTitle.contains(QStringLiteral("planar")));
        // The report's spelling of the scale (core's one label), not a second table of the GUI's.
        QVERIFY(shown.gammaTitle.startsWith(QString::fromStdString(gammaScaleLabel(p.slab.scale))));
        std::size_t collapsed = 0;
        for (std::size_t i = 0; i < 3; ++i)
            for (std::size_t j = 0; j < 2; ++j) {
                const double a = r.grid.amplitudes[i], f = r.grid.frequencies[j];
                const PlanarResult want = runPlanar(c, a, f);
                QCOMPARE(int(r.at(i, j).outcome), int(want.slab.outcome));
                if (want.slab.outcome != Outcome::Collapsed) continue;
                ++collapsed;
                QCOMPARE_LE(std::abs(r.at(i, j).tauC - want.slab.tauC), 1e-12 * want.slab.tauC);
                QCOMPARE_LE(std::abs(shown.at(i, j) - c.tauRef() / want.slab.tauC), 1e-12);
            }
        QVERIFY(collapsed > 0); // the grid reaches the planar critical region
        // The verdict's A_crit at the building's 1 Hz (T = 1 s, every code) is the planar one,
        // searched as kinstab-cli critical --model planar does (from planarNoSlipAmplitude).
        QVERIFY(w->lastCheck().has_value());
        const CodeVerdict& ubc = w->lastCheck()->codes.front();
        const CriticalResult crit =
            criticalAmplitude(planarPoint(c), 1.0, planarNoSlipAmplitude(c), p.critical);
        QVERIFY(crit.amplitude && ubc.aCrit);
        QCOMPARE(*ubc.aCrit, *crit.amplitude);
        QCOMPARE(w->verdictPanel()->rowCount(), 4);
        // Chapter VI: the planar A_crit lies below the 1-DOF one (A_crit(1 Hz) = 0.95-1.00, ch. V).
        QVERIFY(*ubc.aCrit < 0.95);
        // Picking a point shows its planar history.
        w->surfaceView()->selectPoint(2, 0);
        QVERIFY(w->pickedPlanarRun().has_value());
        QCOMPARE(int(w->pickedPlanarRun()->result.slab.outcome), int(r.at(2, 0).outcome));
        QVERIFY(w->planarHistoryChart()->sampleCount() > 10);
        QVERIFY(w->planarHistoryChart()->isVisibleTo(w.get()));
        // Teaching follows the pick with the planar model that made the surface (issue 30: it
        // animated the 1-DOF slab), with the project's planar inputs.
        const TeachingParams t = w->findChild<TeachingView*>()->params();
        QVERIFY(t.model == TeachingModel::Planar);
        QCOMPARE(t.fyHz, p.planar.fyHz);
        QCOMPARE(t.ayRatio, p.planar.ayRatio);
        QCOMPARE(t.amplitude, r.grid.amplitudes[2]);
        // New: nothing said of this run stays, neither the tab's model nor the status line.
        QTabWidget* tabs = nullptr;
        for (QTabWidget* t : w->findChildren<QTabWidget*>())
            if (t->count() > 0 && t->tabText(0).startsWith(QStringLiteral("γc surface"))) tabs = t;
        QVERIFY(tabs);
        QCOMPARE(tabs->tabText(0), QStringLiteral("γc surface — planar"));
        w->newProject();
        QCOMPARE(tabs->tabText(0), QStringLiteral("γc surface"));
        for (QLabel* l : w->statusBar()->findChildren<QLabel*>())
            QVERIFY2(!l->text().contains("Done"), qPrintable(l->text()));
    }

    void saveOpenKeepsPlanarSettings() {
        modelCombo()->setCurrentIndex(1);
        setText("fy", "2.5");
        setText("ayRatio", "0.45");
        setText("theta", "12");
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("planar.json"));
        QCOMPARE(w->saveProjectAs(path), QString());
        w->newProject();
        QVERIFY(w->project().model == ModelKind::Slab1D);
        QVERIFY(w->openProject(path, true));
        const Project p = w->project();
        QVERIFY(p.model == ModelKind::Planar);
        QCOMPARE(p.planar.fyHz, 2.5);
        QCOMPARE(p.planar.ayRatio, 0.45);
        QCOMPARE(p.planar.theta, 12.0);
        QCOMPARE(modelCombo()->currentIndex(), 1);
        QVERIFY(field("fy")->isVisibleTo(w.get()));
        QCOMPARE(loadProject(path.toStdString()).planar, p.planar);
    }

    void cancelStopsPlanarSweep() {
        modelCombo()->setCurrentIndex(1);
        w->gridPanel()->setRanges(GridRanges{0.6, 1.5, 0.01, 0.25, 3.0, 0.05}); // ~5000 points
        w->runAction()->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(w->runner()->snapshot().completed > 2, 60000);
        w->cancelAction()->trigger();
        QVERIFY(waitFinished(30000));
        const SweepResult& r = w->lastSweep();
        QVERIFY(r.completed > 0 && r.completed < r.grid.size());
        QVERIFY(!w->lastCheck().has_value());
        QVERIFY(w->runAction()->isEnabled());
    }
};

QTEST_MAIN(TestPlanarWindow)
#include "tst_planar_window.moc"
