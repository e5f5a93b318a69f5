// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow, continued: the planar model (docs/user-guide.md "model (1-DOF / planar)"). The sweep,
// the A_crit(f) curve and the design check run planarPoint of the project's planar case; a picked
// point shows its planar history (δx, δy). Everything else (surface, overlays, slice, verdict)
// is model-blind.

#include "ui/MainWindow.h"
#include "ui/ModelPanel.h"
#include "ui/PlanarHistoryChart.h"

#include <QLabel>
#include <QStackedWidget>
#include <QTabWidget>

namespace kinstab::ui {

std::optional<AnalysisRequest> MainWindow::runRequest(const Project& p) {
    const bool planar = p.model == ModelKind::Planar;
    m_centre->setTabText(0, planar ? tr("γc surface — planar") : tr("γc surface"));
    try {
        return surfaceRunRequest(p); // reads the planar model's vertical record
    } catch (const std::exception& e) {
        m_status->setText(QString::fromStdString(e.what()));
        return std::nullopt;
    }
}

QString MainWindow::modelTitle() const {
    return m_results.surface() && m_results.surface()->planar ? tr(" (planar)") : QString();
}

void MainWindow::pickPlanar(double amplitude, double frequency) {
    m_results.setPicked(std::nullopt,
                        runPlanarPoint(*m_results.surface()->planarCase(), amplitude, frequency));
    m_planarHistory->setRun(*m_results.pickedPlanar());
    m_historyStack->setCurrentWidget(m_planarHistory);
}

} // namespace kinstab::ui
