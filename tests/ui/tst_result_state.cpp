// SPDX-License-Identifier: GPL-3.0-or-later
// Results bound to their inputs (issue 13, ui/ResultState.h), in the offscreen window (2D heat
// map): Open clears every result; a code-only change keeps A_crit and re-judges the verdict at
// once; a sweep-input change dims every dependent result until a run with the new inputs; after
// Cancel the points never computed are drawn "not computed", distinct from stable.

#include "WindowFields.h"
#include "core/check/RecordAnalysis.h"
#include "core/codes/CodeSet.h"
#include "core/io/Project.h"
#include "ui/BuildingPanel.h"
#include "ui/CodesPanel.h"
#include "ui/ColourBar.h"
#include "ui/CriticalChart.h"
#include "ui/ExcitationPanel.h"
#include "ui/GridPanel.h"
#include "ui/HeatMapView.h"
#include "ui/HistoryChart.h"
#include "ui/MainWindow.h"
#include "ui/ModelPanel.h"
#include "ui/NumberField.h"
#include "ui/RecordInput.h"
#include "ui/SlabPanel.h"
#include "ui/StaleFrame.h"
#include "ui/SurfaceView.h"
#include "ui/VerdictPanel.h"

#include <QAction>
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QLineSeries>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <memory>

using namespace kinstab;
using namespace kinstab::ui;

class TestResultState : public QObject {
    Q_OBJECT
private:
    std::unique_ptr<MainWindow> w;
    QTemporaryDir dir_;

    void setText(const char* name, const QString& text) {
        QLineEdit* e = testing::namedField(w.get(), name)->lineEdit();
        e->selectAll();
        QTest::keyClicks(e, text); // typed, as a user would
        if (e->text() != text) e->setText(text);
    }
    // The paper's critical region at 1 Hz (Furgerson 1980, Figs. 28-34), small enough for a test.
    void runSmallSweep() {
        w->gridPanel()->setRanges(GridRanges{0.9, 1.1, 0.05, 0.5, 1.25, 0.25});
        QSignalSpy spy(w.get(), &MainWindow::sweepFinished);
        w->runAction()->trigger();
        QVERIFY(spy.wait(120000));
        QVERIFY(w->lastCheck().has_value());
        QVERIFY(!w->results().surfaceStale());
    }
    // The UBC 1976 zone box (items 0-4) of the codes panel.
    QComboBox* ubcZone() {
        for (QComboBox* c : w->codesPanel()->findChildren<QComboBox*>())
            if (c->count() == 5 && c->itemText(4) == QLatin1String("4")) return c;
        qFatal("no UBC zone box");
    }
    static bool lineShown(const QWidget* frame) {
        for (const QLabel* l : frame->findChildren<QLabel*>())
            if (l->isVisible() && l->text() == StaleFrame::staleText()) return true;
        return false;
    }

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear(); // a first start: the paper's 16-story example
    }
    void init() {
        w = std::make_unique<MainWindow>();
        w->show();
        QVERIFY(QTest::qWaitForWindowExposed(w.get()));
    }
    void cleanup() { w.reset(); }

    void openingSecondProjectClearsResults() {
        runSmallSweep();
        w->surfaceView()->selectPoint(2, 2); // A = 1.0, f = 1.0: collapses (paper, ch. V)
        QVERIFY(w->pickedRun().has_value());
        QVERIFY(w->historyChart()->sampleCount() > 10);
        // A second project: the same building with another friction coefficient.
        Project other = w->project();
        other.name = "second project";
        other.slab.slab.mu = 0.5;
        const QString path = dir_.filePath("second.json");
        saveProject(other, path.toStdString());
        QVERIFY(w->openProject(path, true));

        QVERIFY(w->windowTitle().startsWith("second.json"));
        QVERIFY(w->surfaceView()->data().empty());
        QVERIFY(w->surfaceView()->overlays().aCrit.empty());
        QCOMPARE(w->lastSweep().grid.size(), std::size_t(0));
        QVERIFY(!w->lastCheck().has_value());
        QVERIFY(!w->pickedRun().has_value());
        QCOMPARE(w->historyChart()->sampleCount(), 0);
        // The verdict asks for a run; nothing is dimmed, since nothing is shown.
        QCOMPARE(w->verdictPanel()->verdictText(0), QStringLiteral("press Run"));
        QVERIFY(!w->surfaceView()->isStale());
        QVERIFY(!w->verdictFrame()->isStale());
        QVERIFY(!w->criticalFrame()->isStale());
    }

    // Open while a sweep runs: the sweep stops, and what it had computed is not shown under the
    // project just opened.
    void openingDuringSweepDropsItsResults() {
        w->gridPanel()->setRanges(GridRanges{0.6, 1.5, 0.01, 10.0, 30.0, 0.1}); // seconds of work
        QSignalSpy spy(w.get(), &MainWindow::sweepFinished);
        w->runAction()->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(w->runner()->snapshot().completed > 20, 20000);
        QTRY_VERIFY_WITH_TIMEOUT(!w->surfaceView()->data().empty(), 5000); // partial surface
        const QString path = dir_.filePath("opened-while-running.json");
        saveProject(w->project(), path.toStdString());
        QVERIFY(w->openProject(path, true));
        QVERIFY(spy.count() > 0 || spy.wait(10000));
        QTest::qWait(2 * SweepRunner::updateIntervalMs); // no late partial result either
        QVERIFY(w->surfaceView()->data().empty());
        QCOMPARE(w->lastSweep().grid.size(), std::size_t(0));
        QVERIFY(!w->lastCheck().has_value());
        QVERIFY(w->runAction()->isEnabled());
    }

    // Before any run the A_crit(f) chart's code lines follow the code inputs at once (issue 30:
    // it kept the previous ratios until the first Run).
    void codeLinesFollowTheCodesBeforeAnyRun() {
        ubcZone()->setCurrentText("3");
        const Project p = w->project();
        const double ratio = runCodes(p.building, p.codes).front().topRatio; // UBC 1976
        auto* chart = w->findChild<CriticalChart*>();
        QVERIFY(chart);
        bool drawn = false;
        for (QAbstractSeries* s : chart->chart()->series())
            if (auto* l = qobject_cast<QLineSeries*>(s); l && l->count() > 0)
                drawn = drawn || std::abs(l->at(0).y() - ratio) < 1e-12;
        QVERIFY2(drawn, qPrintable(QString::number(ratio)));
    }
    // A change of system with T entered changes no result (it only picks the period formulas;
    // K, R, q are the codes' own inputs), and the panel says so beside the field.
    void systemSaysWhatItDrives() {
        BuildingPanel* b = w->buildingPanel();
        QVERIFY(w->project().building.period.has_value()); // the paper's T = 1.0 s
        const std::vector<CodeResult> before = runCodes(w->project().building, w->project().codes);
        QVERIFY(b->systemNote().contains("changes no result"));
        for (QComboBox* c : b->findChildren<QComboBox*>())
            if (c->toolTip().contains("period formula"))
                c->setCurrentIndex((c->currentIndex() + 1) % c->count());
        const std::vector<CodeResult> after = runCodes(w->project().building, w->project().codes);
        for (std::size_t i = 0; i < before.size(); ++i)
            QCOMPARE(after[i].topRatio, before[i].topRatio);
        for (QCheckBox* c : b->findChildren<QCheckBox*>())
            c->setChecked(true); // estimate T by each code's formula
        QVERIFY(b->systemNote().contains("sets each code's period formula"));
    }
    void codeOnlyChangeKeepsACritAndUpdatesVerdict() {
        runSmallSweep();
        const CodeVerdict before = w->lastCheck()->codes.front(); // UBC 1976
        const std::size_t completed = w->lastSweep().completed;
        const auto aCritCurve = w->surfaceView()->overlays().aCrit;
        QVERIFY(!aCritCurve.empty());
        QVERIFY(before.aCrit.has_value());

        ubcZone()->setCurrentText("3"); // Z = 3/4 instead of 1: a code input only
        // Independent: the code ratio of the new inputs straight from core.
        const Project p = w->project();
        const std::vector<CodeResult> codes = runCodes(p.building, p.codes);
        QCOMPARE_LT(codes.front().topRatio, 0.8 * before.ratio); // the zone did change it
        // Kept: the surface, the A_crit(f) curve and A_crit at f = 1/T; no new sweep.
        QVERIFY(!w->results().surfaceStale());
        QVERIFY(!w->surfaceView()->isStale());
        QCOMPARE(w->lastSweep().completed, completed);
        QCOMPARE(w->surfaceView()->overlays().aCrit, aCritCurve);
        // Re-judged at once against the new ratio (chapter V rule: margin = A_crit / ratio).
        QVERIFY(!w->results().checkStale());
        QVERIFY(!w->verdictFrame()->isStale());
        const CodeVerdict& after = w->lastCheck()->codes.front();
        QCOMPARE(after.aCrit, before.aCrit);
        QCOMPARE(after.ratio, codes.front().topRatio);
        QCOMPARE_LE(std::abs(*after.margin - *before.aCrit / codes.front().topRatio), 1e-12);
        QVERIFY(*after.margin > *before.margin);
        QCOMPARE(w->verdictPanel()->verdictText(0), QStringLiteral("overstress governs"));

        // A new building period moves f = 1/T off the frequency A_crit was found at: the
        // verdict is stale (A_crit there needs a search) while the surface stays current.
        setText("period", "0.8");
        QVERIFY(w->results().checkStale());
        QVERIFY(w->verdictFrame()->isStale());
        QVERIFY(lineShown(w->verdictFrame()));
        QVERIFY(!w->results().surfaceStale());
        QVERIFY(!w->surfaceView()->isStale());
    }

    void sweepInputChangeMarksStale() {
        runSmallSweep();
        w->surfaceView()->selectPoint(2, 2);
        const QString mu = testing::namedField(w.get(), "mu")->lineEdit()->text();
        setText("mu", "0.5"); // the slab's friction: every result depends on it
        QVERIFY(w->results().surfaceStale());
        QVERIFY(w->results().checkStale());
        QVERIFY(w->surfaceView()->isStale());
        for (StaleFrame* f :
             {w->sliceFrame(), w->historyFrame(), w->criticalFrame(), w->verdictFrame()}) {
            QVERIFY(f->isStale());
            QVERIFY(lineShown(f));
        }
        QVERIFY(lineShown(w->surfaceView()));
        // The stale results are still there (dimmed), not silently replaced.
        QVERIFY(!w->surfaceView()->data().empty());
        QVERIFY(w->lastCheck().has_value());

        setText("mu", mu); // back to the inputs they were made with: current again
        QVERIFY(!w->results().surfaceStale());
        QVERIFY(!w->historyFrame()->isStale());
        QVERIFY(!lineShown(w->surfaceView()));

        // Switching the model is a sweep input too (the issue: results stayed under it).
        const Project p = w->project();
        w->modelPanel()->load(ModelKind::Planar, p.planar);
        QVERIFY(w->results().surfaceStale());
        QVERIFY(w->surfaceView()->isStale());
        w->modelPanel()->load(ModelKind::Slab1D, p.planar);
        QVERIFY(!w->results().surfaceStale());

        setText("mu", "0.5");
        QVERIFY(w->results().surfaceStale());
        runSmallSweep(); // a run with the new inputs replaces them
        QVERIFY(!w->surfaceView()->isStale());
        QVERIFY(!w->verdictFrame()->isStale());
        QCOMPARE(w->lastCheck()->codes.size(), std::size_t(4));
    }

    // The record example: its critical peak serves every code (one peak for the record), so a
    // code-only change re-judges at once; a slab change makes the record run stale.
    void recordVerdictFollowsCodeInputs() {
        QVERIFY(w->openProject(KINSTAB_SOURCE_DIR "/resources/examples/paper-16-story-record.json",
                               true));
        QSignalSpy spy(w.get(), &MainWindow::recordRunFinished);
        w->runAction()->trigger();
        QVERIFY(spy.wait(120000));
        QVERIFY(w->lastRecordRun() && w->lastRecordRun()->analysis);
        const RecordAnalysis& a = *w->lastRecordRun()->analysis;
        QVERIFY(a.critical && a.critical->peak);
        QVERIFY(w->lastCheck().has_value());

        ubcZone()->setCurrentText("3");
        const Project p = w->project();
        const std::vector<CodeResult> codes = runCodes(p.building, p.codes);
        QVERIFY(!w->results().checkStale());
        QVERIFY(!w->results().recordStale());
        const CodeVerdict& ubc = w->lastCheck()->codes.front();
        QCOMPARE(ubc.ratio, codes.front().topRatio);
        QCOMPARE(ubc.aCrit, a.critical->peak);
        QCOMPARE_LE(std::abs(*ubc.margin - *a.critical->peak / codes.front().topRatio), 1e-12);

        setText("mu", "0.5");
        QVERIFY(w->results().recordStale());
        QVERIFY(w->results().checkStale());
        QVERIFY(w->historyFrame()->isStale());
        QVERIFY(
            w->excitationPanel()->recordInput()->resultText().startsWith(StaleFrame::staleText()));
    }

    void cancelDrawsNotComputedPoints() {
        // 18 291 points at 10-30 Hz (seconds of work, see tst_mainwindow): cancelled early.
        w->gridPanel()->setRanges(GridRanges{0.6, 1.5, 0.01, 10.0, 30.0, 0.1});
        QSignalSpy spy(w.get(), &MainWindow::sweepFinished);
        w->runAction()->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(w->runner()->snapshot().completed > 20, 20000);
        w->cancelAction()->trigger();
        QVERIFY(spy.count() > 0 || spy.wait(10000));
        const SweepResult& r = w->lastSweep();
        QVERIFY(r.completed < r.grid.size());
        const int missing = static_cast<int>(r.grid.size() - r.completed);
        QCOMPARE(w->surfaceView()->notComputedCount(), missing);
        QVERIFY(w->surfaceView()->legendText().contains(QStringLiteral("not computed")));
        // Not computed is a colour no γc takes, least of all stable's (γc = 0).
        for (int k = 0; k <= 100; ++k)
            QVERIFY(gammaColor(k / 100.0) != notComputedColor());
        const QImage img = w->surfaceView()->renderImage(QSize(600, 450));
        long grey = 0;
        for (int y = 0; y < img.height(); ++y)
            for (int x = 0; x < img.width(); ++x)
                grey += QColor(img.pixel(x, y)) == notComputedColor();
        // Most of the grid was not computed: most of the plot area is drawn in that colour.
        QVERIFY2(grey > 600 * 450 / 4, qPrintable(QString::number(grey)));
    }
};

QTEST_MAIN(TestResultState)
#include "tst_result_state.moc"
