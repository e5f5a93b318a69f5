// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow, continued: File → Export surface (CSV/JSON) and Export chart (PNG/SVG).

#include "core/io/JsonText.h"
#include "core/io/ResultJson.h"
#include "core/io/SurfaceJson.h"
#include "ui/AtomicSave.h"
#include "ui/ChartExport.h"
#include "ui/MainWindow.h"
#include "ui/ProjectFolder.h"

#include <QFileDialog>
#include <QLabel>
#include <QMessageBox>

namespace kinstab::ui {

void MainWindow::exportSurface() {
    if (!m_results.surface() || m_results.surface()->gamma.empty()) {
        m_status->setText(tr("Nothing to export: run a sweep first"));
        return;
    }
    const SweepResult& sweep = m_results.surface()->sweep; // with the inputs it was run with
    const Slab1DCase& sweepCase = m_results.surface()->slabCase;
    const std::optional<PlanarCase>& sweepPlanar = m_results.surface()->planar;
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export surface"), inProjectFolder(m_path, QStringLiteral("surface.csv")),
        tr("CSV (*.csv);;JSON (*.json)"));
    if (path.isEmpty()) return;
    std::string text;
    try { // the writers refuse a non-finite number where one is promised
        if (path.endsWith(QLatin1String(".json"), Qt::CaseInsensitive)) {
            // The same object as kinstab-cli surface writes (core/io/SurfaceJson.h).
            text = jsonText(sweepPlanar ? surfaceJson(sweep, *sweepPlanar)
                                        : surfaceJson(sweep, sweepCase),
                            1) +
                   "\n";
        } else {
            text = sweepCsv(sweep, sweepCase.tauRef());
        }
    } catch (const std::exception& e) {
        QMessageBox::warning(this, tr("Export surface"), QString::fromStdString(e.what()));
        return;
    }
    // Atomic: a failed write leaves the old file alone (ui/AtomicSave.h).
    if (const QString e = saveAtomically(path, QByteArray::fromStdString(text)); !e.isEmpty())
        QMessageBox::warning(this, tr("Export surface"), e);
    else
        m_status->setText(tr("Surface written to %1").arg(path));
}

void MainWindow::exportChart(QChartView* view, const QString& name) {
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export chart"), inProjectFolder(m_path, name + QStringLiteral(".svg")),
        tr("SVG vector (*.svg);;PNG image (*.png)"));
    if (path.isEmpty()) return;
    const QString error = ui::exportChart(view, path);
    if (!error.isEmpty())
        QMessageBox::warning(this, tr("Export chart"), error);
    else
        m_status->setText(tr("Chart written to %1").arg(path));
}

} // namespace kinstab::ui
