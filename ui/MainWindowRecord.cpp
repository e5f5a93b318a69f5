// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow, continued: a record as the excitation (docs/theory.md §7; docs/user-guide.md). Run
// computes, in the record runner's worker, the single run of the slab under the scaled record and
// the critical scale; the history chart shows delta(tau) and the motion, the verdict panel compares
// the critical peak with the code ratios. A record has no (A, f) surface.

#include "ui/ExcitationPanel.h"
#include "ui/HistoryChart.h"
#include "ui/MainWindow.h"
#include "ui/ModelPanel.h"
#include "ui/RecordInput.h"
#include "ui/RunProgress.h"
#include "ui/VerdictPanel.h"

#include <QAction>
#include <QDockWidget>
#include <QLabel>

namespace kinstab::ui {

namespace {
QString runSummary(const RecordAnalysis& a, double tstar) {
    const SlabResult& r = a.run;
    QString s = QObject::tr("Record scaled to %1 g (factor %2): ")
                    .arg(a.peak, 0, 'f', 3)
                    .arg(a.scaleFactor, 0, 'f', 3);
    if (r.outcome == Outcome::Collapsed)
        s += QObject::tr("collapses at τc = %1 (t = %2 s)")
                 .arg(r.tauC, 0, 'f', 3)
                 .arg(r.tauC * tstar, 0, 'f', 2);
    else
        s += QString::fromStdString(outcomeName(r.outcome));
    s += QObject::tr(", max |δ| = %1, %2 slips").arg(r.maxAbsDelta, 0, 'f', 3).arg(r.slipIntervals);
    if (a.critical)
        s += a.critical->peak ? QObject::tr(". Critical peak %1 g (factor %2)")
                                    .arg(*a.critical->peak, 0, 'f', 4)
                                    .arg(*a.critical->factor, 0, 'f', 3)
                              : QObject::tr(". No collapse up to the search limit");
    return s;
}
} // namespace

void MainWindow::buildRecordRun() {
    m_recordRunner = new RecordRunner(this);
    connect(m_recordRunner, &RecordRunner::progress, this, &MainWindow::showProgress);
    connect(m_recordRunner, &RecordRunner::finished, this, &MainWindow::showRecordFinished);
}

void MainWindow::runRecord() {
    if (!inputsValid() || m_recordRunner->isRunning() || m_runner->isRunning()) return;
    RecordAnalysisInput in;
    in.slab = currentCase();
    in.record = *m_excitation->record();
    in.search = m_project.critical;
    in.codes = m_codeResults;
    m_results.startRecordRun(); // the old run and verdicts go: the new run replaces them
    m_history->clearRun();
    showVerdict();
    showStaleness();
    m_recordRunner->start(in);
    m_progress->start(0, tr("slab runs"));
    // The GUI runs records with the 1-DOF model; the planar slab under records is kinstab-cli's.
    const bool planar = m_modelPanel && m_modelPanel->isPlanar();
    m_status->setText(tr("Running the record and searching its critical scale… (a record has "
                         "no (A, f) surface%1)")
                          .arg(planar ? tr("; records run the 1-DOF model here — planar: "
                                           "kinstab-cli simulate --model planar --record")
                                      : QString()));
    updateRunState();
}

void MainWindow::showRecordFinished(const RecordOutput& out) {
    m_progress->finish();
    if (!m_results.awaits(ResultState::Run::Record)) { // a run of the project closed by Open/New
        updateRunState();
        emit recordRunFinished();
        return;
    }
    m_results.runEnded();
    m_results.setRecordRun(out);
    RecordInput* input = m_excitation->recordInput();
    if (!out.analysis) {
        input->setResult(QString::fromStdString(out.error), true);
        m_status->setText(QString::fromStdString(out.error));
    } else {
        const RecordAnalysis& a = *out.analysis;
        if (out.history) m_history->setRun(*out.history);
        if (a.critical)
            m_results.setCheck(DesignCheckResult{a.verdicts, a.critical->runs},
                               {CheckSource::Source::Record, m_project.critical.to, *a.critical,
                                m_project.critical});
        const QString summary = runSummary(a, currentCase().tstar);
        // The result is shown under the record's inputs: bring their dock to the front.
        for (QWidget* w = m_excitation; w; w = w->parentWidget())
            if (auto* dock = qobject_cast<QDockWidget*>(w)) dock->raise();
        input->setResult(summary, false);
        m_status->setText(
            out.cancelled
                ? tr("Cancelled: %1").arg(summary)
                : tr("%1 (%2 s)").arg(summary).arg(a.runSeconds + a.criticalSeconds, 0, 'f', 2));
    }
    inputsChanged(); // code inputs changed while it ran: re-judge now
    if (out.analysis && !out.cancelled) startAssessment();
    updateRunState();
    emit recordRunFinished();
}

} // namespace kinstab::ui
