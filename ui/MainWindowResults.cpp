// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow, continued: the shown results against the inputs now on the panels
// (ui/ResultState.h). New and Open clear every result; an input change re-judges the verdicts
// where the kept A_crit serves and dims every result made with other inputs, with the line
// "inputs changed — Run to update", until a run with the new inputs replaces it.

#include "core/assessment/RunAssessment.h"
#include "core/slab/VerticalRecord.h"
#include "ui/BlockMapView.h"
#include "ui/CriticalChart.h"
#include "ui/ExcitationPanel.h"
#include "ui/GridPanel.h"
#include "ui/HistoryChart.h"
#include "ui/MainWindow.h"
#include "ui/PlanarHistoryChart.h"
#include "ui/RecordInput.h"
#include "ui/SliceChart.h"
#include "ui/StaleFrame.h"
#include "ui/SurfaceView.h"
#include "ui/VerdictPanel.h"

#include <QLabel>
#include <QStackedWidget>
#include <QTabWidget>

namespace kinstab::ui {

const SweepResult& MainWindow::lastSweep() const {
    static const SweepResult none;
    return m_results.surface() ? m_results.surface()->sweep : none;
}

std::optional<PlanarCase> MainWindow::sweepPlanarCase() const {
    return m_results.surface() ? m_results.surface()->planarCase() : std::nullopt;
}

void MainWindow::clearResults() {
    // A run still going belongs to the previous inputs: stopped, and its end is not shown.
    m_runner->cancel();
    m_recordRunner->cancel();
    m_blockMap->clear();
    m_assessJob->cancel();
    m_assessment.reset();
    m_results.clear();
    // Nothing said of the previous project's run stays: the surface tab's model and the status.
    m_centre->setTabText(0, tr("γc surface"));
    m_status->clear();
    m_overlays.aCrit.clear();
    m_selA = m_selF = -1;
    m_surface->setData(GammaGrid{});
    m_slice->clearSlice();
    m_history->clearRun();
    m_planarHistory->clearRun();
    m_historyStack->setCurrentWidget(m_history);
    const SweepGrid grid = m_gridPanel->grid();
    if (!grid.frequencies.empty())
        m_critical->setData(m_overlays, grid.frequencies.front(), grid.frequencies.back());
    m_excitation->recordInput()->setResult(QString(), false);
    refreshOverlays();
    showVerdict();
    showStaleness();
}

void MainWindow::inputsChanged() {
    std::optional<InputFingerprint> now;
    if (inputsValid()) {
        try {
            now = fingerprintOf(project());
        } catch (const std::exception&) {
            now.reset(); // inputs that cannot be written are not the inputs of any result
        }
    }
    m_results.setInputs(now, m_codeResults);
    // A kept check is shown (re-judged, or dimmed when stale) unless the codes failed: then
    // updateCodes' message naming the bad input stays.
    if ((m_results.check() || fullAssessment()) &&
        !(m_results.checkStale() && m_codeResults.empty()))
        m_verdict->setAssessment(currentAssessment(), assessmentScope());
    showStaleness();
}

const Assessment* MainWindow::fullAssessment() const {
    if (!m_assessment || !inputsValid()) return nullptr;
    try {
        if (m_assessment->first == fingerprintOf(project())) return &m_assessment->second;
    } catch (const std::exception&) {
    }
    return nullptr;
}

// What check and the report would say for the inputs shown: core's runAssessment, run after each
// run of the window (it adds what the run did not compute: the sine's checks of a record project,
// the floor checks at the slab's level). Superseded by the next start; dropped on a change.
void MainWindow::startAssessment() {
    if (!inputsValid()) return;
    Project p;
    InputFingerprint key;
    try {
        p = project();
        key = fingerprintOf(p);
    } catch (const std::exception&) {
        return;
    }
    m_assessJob->start<std::optional<Assessment>>(
        [p](JobContext& job) -> std::optional<Assessment> {
            auto& control = static_cast<AnalysisJobContext&>(job).analysis;
            try {
                std::optional<PlanarCase> planar;
                if (p.model == ModelKind::Planar) planar = planarCaseWithVertical(p.slab, p.planar);
                const AssessmentRun run = runAssessment(p, planar, control);
                if (run.cancelled) return std::nullopt;
                return run.assessment;
            } catch (const std::exception&) {
                return std::nullopt; // the run's own panels say what was wrong with the inputs
            }
        },
        [this, key](std::optional<Assessment> a) {
            if (a) m_assessment.emplace(key, std::move(*a));
            showVerdict();
            emit assessmentFinished();
        },
        std::make_shared<AnalysisJobContext>());
    showVerdict(); // says the whole assessment is being computed
}

// The assessment of what ran (core composes it): the whole one when it is of the inputs shown,
// else the check of the last run, on the enveloped sine (or the planar model) or on the record.
Assessment MainWindow::currentAssessment() const {
    if (const Assessment* full = fullAssessment()) return *full;
    AssessmentParts parts;
    if (m_results.checkBasis().source == CheckSource::Source::Record) {
        parts.record = m_results.check()->codes;
        const auto& run = m_results.recordRun();
        if (run && run->analysis) parts.recordName = run->analysis->ground.name;
    } else {
        parts.sine = *m_results.check();
    }
    return composeAssessment(project(), parts);
}

// What the verdict table holds when it is not the project's whole assessment: this run's checks,
// while the rest is computed or after it could not be.
QString MainWindow::assessmentScope() const {
    if (fullAssessment()) return {};
    return m_assessJob->isRunning()
               ? tr("Assessing the whole project… Until it is done the table shows this run's "
                    "checks only; the governing check may change.")
               : tr("This run's checks only, not the whole project's assessment.");
}

void MainWindow::showVerdict() {
    if (m_results.check() || fullAssessment())
        m_verdict->setAssessment(currentAssessment(), assessmentScope());
    else
        m_verdict->setCodeResults(m_codeResults);
}

void MainWindow::showStaleness() {
    const bool surface = m_results.surfaceStale();
    m_surface->setStale(surface);
    m_sliceFrame->setStale(surface);
    m_criticalFrame->setStale(surface);
    const bool pickStale =
        (m_results.picked() || m_results.pickedPlanar()) && m_results.surfaceStale();
    const bool recordStale = m_results.recordRun() && m_results.recordRun()->history &&
                             !m_results.picked() && m_results.recordStale();
    m_historyFrame->setStale(pickStale || recordStale);
    m_excitation->recordInput()->setResultStale(m_results.recordStale());
    m_verdictFrame->setStale(m_results.checkStale());
}

} // namespace kinstab::ui
