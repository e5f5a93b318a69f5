// SPDX-License-Identifier: GPL-3.0-or-later
// A record as the excitation in the desktop window (docs/theory.md §7; docs/user-guide.md),
// offscreen: choosing Record, a sample file and Run gives the same single run and critical scale as
// the core call (core/check/RecordAnalysis.h, itself checked against a brute-force scan in
// tst_record_critical), a broken file shows its reason beside the field and blocks Run, and a
// project with a record survives save and open.

#include "core/assessment/RunAssessment.h"
#include "core/check/RecordAnalysis.h"
#include "core/io/Project.h"
#include "ui/ExcitationPanel.h"
#include "ui/HistoryChart.h"
#include "ui/MainWindow.h"
#include "ui/NumberField.h"
#include "ui/RecordInput.h"
#include "ui/RecordPreview.h"
#include "ui/SurfaceView.h"
#include "ui/VerdictPanel.h"

#include <QAction>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QSettings>
#include <QSignalSpy>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>

#include <memory>

using namespace kinstab;
using namespace kinstab::ui;

namespace {
const QString kElCentro =
    QStringLiteral(KINSTAB_SOURCE_DIR "/resources/records/RSN6_IMPVALL.I_I-ELC180.AT2");
}

class TestRecordInput : public QObject {
    Q_OBJECT
private:
    std::unique_ptr<MainWindow> w;
    RecordInput* input() { return w->excitationPanel()->recordInput(); }
    void chooseRecord(const QString& path, const QString& peak) {
        w->excitationPanel()->findChild<QComboBox*>("excitationSource")->setCurrentIndex(1);
        QVERIFY(w->excitationPanel()->usesRecord());
        QLineEdit* file = input()->fileEdit();
        file->setText(path);
        emit file->editingFinished(); // as when the user leaves the field
        input()->peakField()->lineEdit()->setText(peak);
    }
    bool waitRecord(int ms) {
        QSignalSpy spy(w.get(), &MainWindow::recordRunFinished);
        return spy.count() > 0 || spy.wait(ms);
    }

private slots:
    void initTestCase() {
        QStandardPaths::setTestModeEnabled(true);
        QSettings().clear();
    }
    void init() {
        w = std::make_unique<MainWindow>();
        w->show();
        QVERIFY(QTest::qWaitForWindowExposed(w.get()));
    }
    void cleanup() { w.reset(); }

    void runMatchesTheCoreCall() {
        chooseRecord(kElCentro, "1.5");
        QVERIFY2(w->inputsValid(), qPrintable(w->excitationPanel()->problems().join("; ")));
        QVERIFY(w->runAction()->isEnabled());
        w->runAction()->trigger();
        QVERIFY(waitRecord(120000));
        const auto& out = w->lastRecordRun();
        QVERIFY(out && out->analysis);
        // The same analysis straight from core, with the window's inputs.
        RecordAnalysisInput in;
        in.slab = w->currentCase();
        in.record = *w->excitationPanel()->record();
        in.search = w->project().critical;
        const RecordAnalysis core = analyseRecord(in);
        QCOMPARE(outcomeName(out->analysis->run.outcome), std::string("collapsed"));
        QCOMPARE(out->analysis->run.tauC, core.run.tauC);
        QVERIFY(core.critical && core.critical->peak && out->analysis->critical);
        QCOMPARE(*out->analysis->critical->peak, *core.critical->peak);
        QVERIFY(input()->resultText().contains("collapses at τc"));
        QVERIFY(w->historyChart()->sampleCount() > 100);
        // The paper's building: the code ratios are far below the record's critical peak.
        QVERIFY(w->verdictPanel()->rowCount() > 0);
        QCOMPARE(w->verdictPanel()->verdictText(0), QString("overstress governs"));
        // Until the whole assessment is in, the table says it holds this run's checks only.
        QCOMPARE(!w->verdictPanel()->governingText().startsWith("Governing"),
                 w->fullAssessment() == nullptr);
        // Then the project's whole assessment, as kinstab-cli check gives it: the enveloped
        // sine's checks and the record's, with their basis (core/assessment).
        // (It may already be in: the record's envelope fit takes 0.05 ms since issue 34. Both
        // are set on this thread, so a null here means the signal is still to come.)
        QSignalSpy assessed(w.get(), &MainWindow::assessmentFinished);
        QVERIFY(w->fullAssessment() || assessed.wait(120000));
        QVERIFY(w->fullAssessment());
        AnalysisControl control;
        const Assessment cli = runAssessment(w->project(), std::nullopt, control).assessment;
        QCOMPARE(w->verdictPanel()->rowCount(), int(cli.checks.size()));
        for (int row = 0; row < w->verdictPanel()->rowCount(); ++row)
            QCOMPARE(w->verdictPanel()->checkText(row), QString::fromStdString(cli.checks[row].id));
        QCOMPARE(w->verdictPanel()->basisText(int(cli.checks.size()) - 1), QString("record"));
        QVERIFY(w->verdictPanel()->governingText().startsWith(
            "Governing: " + QString::fromStdString(cli.governingCheck()->id)));
        QVERIFY(!w->verdictPanel()->governingText().contains("this run's checks"));
        // The surface tab says why it is empty, and stops saying so for the sine.
        QVERIFY(w->surfaceView()->notice().contains("no γc(A, f) surface"));
        w->excitationPanel()->findChild<QComboBox*>("excitationSource")->setCurrentIndex(0);
        QVERIFY(w->surfaceView()->notice().isEmpty());
    }
    void cancelKeepsTheRunDropsTheSearch() {
        // A search cancelled before it starts: the single run is there, the critical scale and
        // the verdicts are not (as a cancelled sweep keeps only what it computed).
        RecordAnalysisInput in;
        in.record.file = kElCentro.toStdString();
        in.record.targetPeak = 1.5;
        SweepControl control;
        control.cancel();
        const RecordOutput out = runRecordJob(in, &control);
        QVERIFY(out.analysis && out.cancelled);
        QCOMPARE(outcomeName(out.analysis->run.outcome), std::string("collapsed"));
        QVERIFY(!out.analysis->critical);
        QVERIFY(out.analysis->verdicts.empty());
        QVERIFY(out.history && out.history->history.samples.size() > 100);
    }
    void brokenFileShowsBesideTheField() {
        QTemporaryDir dir;
        const QString bad = dir.filePath("broken.AT2");
        QFile f(bad);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("PEER NGA STRONG MOTION DATABASE RECORD\nx\nACCELERATION IN G\nNPTS= 5, DT= "
                "0.01\n0.1 0.2 zz\n");
        f.close();
        chooseRecord(bad, "");
        const QString message = input()->fileMessage()->text();
        QVERIFY2(message.contains("broken.AT2:"), qPrintable(message)); // FILE:LINE: reason
        QVERIFY(!w->inputsValid());
        QVERIFY(!w->runAction()->isEnabled());
        chooseRecord(dir.filePath("none.AT2"), "");
        QVERIFY(input()->fileMessage()->text().contains("cannot open"));
        QVERIFY(!w->runAction()->isEnabled());
        // A sound file makes Run available again.
        chooseRecord(kElCentro, "");
        QVERIFY(w->runAction()->isEnabled());
    }
    void projectRoundTrip() {
        chooseRecord(kElCentro, "0.8");
        input()->preview()->setFloorFilter(FloorFilterParams{0.7, 0.05, std::nullopt});
        QTemporaryDir dir;
        const QString path = dir.filePath("p.json");
        QCOMPARE(w->saveProjectAs(path), QString());
        const Project saved = loadProject(path.toStdString());
        QVERIFY(saved.record);
        QCOMPARE(saved.record->file, kElCentro.toStdString());
        QCOMPARE(saved.record->targetPeak, std::optional<double>(0.8));
        QVERIFY(saved.record->floor);
        QCOMPARE(saved.record->floor->period, 0.7);
        QCOMPARE(saved.record->floor->damping, 0.05);
        w->newProject();
        QVERIFY(!w->excitationPanel()->usesRecord());
        QVERIFY(w->openProject(path, true));
        QVERIFY(w->excitationPanel()->usesRecord());
        QCOMPARE(projectToJson(w->project()).dump(), projectToJson(saved).dump());
    }
};

QTEST_MAIN(TestRecordInput)
#include "tst_record_input.moc"
