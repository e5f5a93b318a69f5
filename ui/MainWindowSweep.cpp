// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow, continued: the sweep's run (Run, Cancel, its progress and result), the surface's
// slice and the point picked on it, and the inputs the run reads.

#include "core/analysis/RunAnalysis.h"
#include "ui/BlockMapView.h"
#include "ui/BuildingPanel.h"
#include "ui/CodesPanel.h"
#include "ui/CriticalChart.h"
#include "ui/ExcitationPanel.h"
#include "ui/GridPanel.h"
#include "ui/HistoryChart.h"
#include "ui/MainWindow.h"
#include "ui/ModelPanel.h"
#include "ui/PlanarHistoryChart.h"
#include "ui/RunProgress.h"
#include "ui/SlabPanel.h"
#include "ui/SliceChart.h"
#include "ui/SurfaceView.h"
#include "ui/VerdictPanel.h"
#include "ui/teaching/TeachingRun.h"
#include "ui/teaching/TeachingView.h"

#include <QAction>
#include <QLabel>
#include <QStackedWidget>
#include <QStatusBar>

#include <cmath>

namespace kinstab::ui {

namespace {
QString gammaTitle(TauScale s) {
    switch (s) {
    case TauScale::TauRise:
        return QStringLiteral("γc = τ_rise/τc");
    case TauScale::TauMax:
        return QStringLiteral("γc = τ_max/τc");
    case TauScale::TauDur:
        return QStringLiteral("γc = τ_dur/τc");
    case TauScale::One:
        return QStringLiteral("γc = 1/τc");
    }
    return QStringLiteral("γc");
}
} // namespace

Slab1DCase MainWindow::currentCase() const {
    Slab1DCase c = m_project.slab; // duration and paper steps are not on a panel
    m_slabPanel->apply(c);
    c.envelope = m_excitation->envelope();
    c.scale = m_excitation->scale();
    return c;
}

bool MainWindow::inputsValid() const {
    return m_building->isValid() && m_codesPanel->isValid() && m_slabPanel->isValid() &&
           m_modelPanel->isValid() && m_excitation->isValid() && m_gridPanel->isValid();
}

void MainWindow::updateRunState() {
    m_surface->setNotice(
        m_excitation->usesRecord()
            ? tr("A record has no γc(A, f) surface: Run gives its single run (History), its "
                 "critical peak and the verdict per code (Verdict, Excitation). Set Source to "
                 "Enveloped sine for the surface.")
            : QString());
    const bool running =
        m_runner->isRunning() || m_recordRunner->isRunning() || m_blockMap->isRunning();
    m_run->setEnabled(!running && inputsValid());
    m_cancel->setEnabled(running);
    if (running) return;
    QStringList problems = m_building->problems() + m_codesPanel->problems() +
                           m_slabPanel->problems() + m_modelPanel->problems() +
                           m_excitation->problems() + m_gridPanel->problems();
    if (!problems.isEmpty()) {
        m_status->setText(tr("Fix before running — %1").arg(problems.join(QStringLiteral("; "))));
        m_run->setToolTip(problems.join(QLatin1Char('\n')));
    } else {
        m_run->setToolTip(m_modelPanel->isBlock()
                              ? tr("Compute the block's overturning map (Ctrl+R / F5)")
                              : tr("Compute γc over the grid (Ctrl+R / F5)"));
        if (m_status->text().startsWith(tr("Fix before running"))) m_status->clear();
    }
}

void MainWindow::runSweep() {
    if (m_modelPanel->isBlock()) return runBlockMap();
    if (m_excitation->usesRecord()) return runRecord();
    if (!inputsValid() || m_runner->isRunning()) return;
    const Project p = project();
    const std::string e = validateCase(p.slab) + validateGrid(p.grid);
    if (!e.empty()) {
        m_status->setText(QString::fromStdString(e));
        return;
    }
    const std::optional<AnalysisRequest> job = runRequest(p);
    if (!job) return;
    // The old surface, curve, history and verdicts go: the new run replaces them.
    statusBar()->clearMessage(); // "Opened …" must not cover the run's status
    m_results.startSweep(job->slab, job->planarCase());
    m_overlays.aCrit.clear();
    m_history->clearRun();
    m_planarHistory->clearRun();
    showVerdict();
    showStaleness();
    m_runner->start(*job);
    const std::size_t steps = analysisSteps(*job); // the bar's total too
    m_progress->start(static_cast<qint64>(steps), tr("steps"));
    m_status->setText(tr("Running %1 steps: %2 points%3, A_crit at %4 frequencies%5…")
                          .arg(steps)
                          .arg(job->grid.size())
                          .arg(job->planar ? tr(" of the planar model (2–5 ms of CPU each)") : "")
                          .arg(job->criticalFrequencies.size())
                          .arg(job->codes.empty() ? QString() : tr(", the design check")));
    updateRunState();
}

void MainWindow::cancelSweep() {
    m_blockMap->cancel();
    m_runner->cancel();
    m_recordRunner->cancel();
}

void MainWindow::showProgress(qint64 done, qint64 total) {
    m_progress->update(done, total);
}

void MainWindow::showPartial(const SweepResult& r) {
    if (!m_results.awaits(ResultState::Run::Sweep) || !m_results.surface()) return;
    const SurfaceResult& s = *m_results.surface();
    GammaGrid g = gammaGrid(r, s.planar ? s.planar->tauRef() : s.slabCase.tauRef());
    g.gammaTitle = gammaTitle(s.slabCase.scale) + modelTitle();
    m_results.setSweepProgress(r, g);
    m_surface->setData(g);
    updateSlice();
}

void MainWindow::showFinished(const AnalysisResult& out) {
    if (!m_results.awaits(ResultState::Run::Sweep)) { // a run of the project closed by Open/New
        m_progress->finish();
        updateRunState();
        emit sweepFinished();
        return;
    }
    const SweepResult& sweep = *out.surface;
    showPartial(sweep);
    m_overlays.aCrit.clear();
    if (out.critical)
        for (std::size_t j = 0; j < out.critical->amplitude.size(); ++j)
            if (const std::optional<double> a = out.critical->amplitude[j])
                m_overlays.aCrit.emplace_back(out.critical->frequencies[j], *a);
    m_results.setACrit(m_overlays.aCrit);
    refreshOverlays();
    if (out.check)
        m_results.setCheck(*out.check, {CheckSource::Source::Sine, m_project.critical.to, {}, {}});
    m_results.runEnded();
    inputsChanged(); // code inputs changed while it ran: re-judge now
    if (!out.cancelled) startAssessment();
    if (!out.check && out.checkError)
        m_verdict->setError(QString::fromStdString(checkErrorMessage(out)));
    m_progress->finish();
    m_status->setText(out.cancelled ? tr("Cancelled: %1 of %2 points computed and shown (%3 s)")
                                          .arg(sweep.completed)
                                          .arg(sweep.grid.size())
                                          .arg(sweep.wallTimeSeconds, 0, 'f', 2)
                                    : tr("Done: %1 points in %2 s")
                                          .arg(sweep.grid.size())
                                          .arg(sweep.wallTimeSeconds, 0, 'f', 2));
    updateRunState();
    emit sweepFinished();
}

void MainWindow::refreshOverlays() {
    m_surface->setOverlays(m_overlays);
    // The code lines follow the code inputs at once, before any run too: over the surface's
    // frequencies, or the grid's while there is no surface.
    const GammaGrid& g = m_surface->data();
    if (!g.empty()) {
        m_critical->setData(m_overlays, g.frequencies.front(), g.frequencies.back());
        return;
    }
    const SweepGrid grid = m_gridPanel->grid();
    if (!grid.frequencies.empty())
        m_critical->setData(m_overlays, grid.frequencies.front(), grid.frequencies.back());
}

void MainWindow::pickPoint(int ai, int fi) {
    const std::optional<SurfaceResult>& s = m_results.surface();
    if (!s || s->gamma.empty() || ai < 0 || fi < 0) return;
    m_selA = ai;
    m_selF = fi;
    updateSlice();
    const double a = s->gamma.amplitudes[static_cast<std::size_t>(ai)];
    const double f = s->gamma.frequencies[static_cast<std::size_t>(fi)];
    // The teaching tab follows the pick with the model that made the surface (planar too).
    std::string notShown;
    m_teaching->setParams(
        teachingParamsOf(s->slabCase, s->planar, a, f, m_teaching->params(), &notShown));
    if (!notShown.empty())
        m_status->setText(tr("Teaching does not show %1.").arg(QString::fromStdString(notShown)));
    if (s->planar) {
        pickPlanar(a, f);
        return;
    }
    m_historyStack->setCurrentWidget(m_history);
    // Run with the inputs the surface was made with, so the history matches the surface.
    m_results.setPicked(runPoint(s->slabCase, a, f), std::nullopt);
    m_history->setRun(*m_results.picked());
}

void MainWindow::updateSlice() {
    if (!m_results.surface()) return;
    const GammaGrid& gamma = m_results.surface()->gamma;
    const SweepResult& sweep = m_results.surface()->sweep;
    if (m_selF < 0 || gamma.empty() || static_cast<std::size_t>(m_selF) >= gamma.frequencies.size())
        return;
    const auto fi = static_cast<std::size_t>(m_selF);
    std::vector<double> g, t;
    for (std::size_t i = 0; i < gamma.amplitudes.size(); ++i) {
        g.push_back(gamma.at(i, fi));
        const std::size_t k = i * gamma.frequencies.size() + fi;
        t.push_back(sweep.done[k] && sweep.points[k].outcome == Outcome::Collapsed
                        ? sweep.points[k].tauC
                        : std::nan(""));
    }
    m_slice->setSlice(gamma.frequencies[fi], gamma.amplitudes, g, t, gamma.gammaTitle);
}

} // namespace kinstab::ui
