// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow, continued: the menu bar's File and Sweep menus and the sweep's tool bar (Edit is
// in MainWindowEdits.cpp, Help in ui/HelpMenu.h, View's entries come with the docks).

#include "ui/CriticalChart.h"
#include "ui/ExampleProjects.h"
#include "ui/HistoryChart.h"
#include "ui/MainWindow.h"
#include "ui/ProjectInfoPanel.h"
#include "ui/RecentFiles.h"
#include "ui/ReportExport.h"
#include "ui/SliceChart.h"

#include <QAction>
#include <QDir>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>
#include <QToolBar>

namespace kinstab::ui {

void MainWindow::buildFileMenu() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    QAction* a = file->addAction(tr("&New"), QKeySequence::New, this, [this] {
        if (askToSave() != Unsaved::Cancel) newProject();
    });
    a->setToolTip(tr("Start from the default building and slab"));
    file->addAction(tr("&Open…"), QKeySequence::Open, this, &MainWindow::openDialog);
    const auto openAsked = [this](const QString& p) {
        if (askToSave() != Unsaved::Cancel) openProject(p);
    };
    addExampleMenu(file, openAsked);
    m_recent = new RecentFiles(tr("Open &recent"), this);
    connect(m_recent, &RecentFiles::openRequested, this, openAsked);
    file->addMenu(m_recent);
    file->addAction(tr("&Save"), QKeySequence::Save, this, &MainWindow::save);
    QAction* saveAs = file->addAction(tr("Save &as…"), this, &MainWindow::saveAsDialog);
    // QKeySequence::SaveAs is empty on X11 without GNOME or KDE (and on Windows): Ctrl+Shift+S,
    // what those desktops bind, everywhere the platform gives none.
    saveAs->setShortcuts(QKeySequence::keyBindings(QKeySequence::SaveAs).isEmpty()
                             ? QList<QKeySequence>{QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S)}
                             : QKeySequence::keyBindings(QKeySequence::SaveAs));
    saveAs->setObjectName(QStringLiteral("saveAsAction"));
    file->addAction(tr("Project &information…"), this, [this] {
        // Engineer, client, revisions: kept in the project, printed on the report's title block.
        if (ProjectInfoPanel::editInDialog(this, m_project.info))
            statusBar()->showMessage(tr("Project information changed; save to keep it"), 5000);
    });
    file->addSeparator();
    addExportActions(file);
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);
}

// File → Export surface, Export chart, Export report.
void MainWindow::addExportActions(QMenu* file) {
    QAction* exportSurface =
        file->addAction(tr("Export &surface (CSV/JSON)…"), this, &MainWindow::exportSurface);
    exportSurface->setShortcut(Qt::CTRL | Qt::SHIFT | Qt::Key_E);
    QMenu* charts = file->addMenu(tr("Export &chart (PNG/SVG)"));
    charts->addAction(tr("γc and τc against A…"), this,
                      [this] { exportChart(m_slice, QStringLiteral("slice")); });
    charts->addAction(tr("History δ(τ)…"), this,
                      [this] { exportChart(m_history, QStringLiteral("history")); });
    charts->addAction(tr("A_crit(f)…"), this,
                      [this] { exportChart(m_critical, QStringLiteral("acrit")); });
    QAction* report = file->addAction(tr("Export &report (PDF)…"), this, [this] {
        // The same document as `kinstab-cli report` (report/ReportWriter.h).
        exportReportDialog(this, project(), m_path, [this](const QString& out) {
            // In the status line, where it stays until the next message (a 5 s flash was easy
            // to miss), and as a notice that does not block the window.
            const QString text = tr("Report written to %1").arg(QDir::toNativeSeparators(out));
            statusBar()->clearMessage();
            m_status->setText(text);
            auto* notice = new QMessageBox(QMessageBox::Information, tr("Export design report"),
                                           text, QMessageBox::Ok, this);
            notice->setObjectName(QStringLiteral("reportWrittenNotice"));
            notice->setAttribute(Qt::WA_DeleteOnClose);
            notice->setModal(false);
            notice->show();
        });
    });
    report->setShortcut(Qt::CTRL | Qt::Key_E);
    // Also while the 3D view (a window of its own) has the focus.
    report->setShortcutContext(Qt::ApplicationShortcut);
}

void MainWindow::buildActions() {
    buildFileMenu();
    buildEditMenu();

    QMenu* sweep = menuBar()->addMenu(tr("&Sweep"));
    m_run = sweep->addAction(tr("&Run"), this, &MainWindow::runSweep);
    m_run->setShortcuts({QKeySequence(Qt::CTRL | Qt::Key_R), QKeySequence(Qt::Key_F5)});
    m_run->setToolTip(tr("Compute γc over the grid (Ctrl+R / F5)"));
    // F5 must work wherever the focus went back to after a dialog, the 3D view's own window
    // included (a window shortcut is not seen there); a modal dialog still blocks it.
    m_run->setShortcutContext(Qt::ApplicationShortcut);
    m_cancel = sweep->addAction(tr("&Cancel"), this, &MainWindow::cancelSweep);
    m_cancel->setShortcut(Qt::Key_Escape);
    m_cancel->setToolTip(tr("Stop the sweep; points already computed are kept (Esc)"));
    m_cancel->setEnabled(false);
    m_viewMenu = menuBar()->addMenu(tr("&View"));

    QToolBar* bar = addToolBar(tr("Sweep"));
    bar->setObjectName(QStringLiteral("sweepToolBar"));
    bar->setToolButtonStyle(Qt::ToolButtonTextOnly);
    bar->addAction(m_run);
    bar->addAction(m_cancel);
}

} // namespace kinstab::ui
