// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow, continued: undo/redo of the inputs (Edit menu), the modified mark, and the
// Save / Discard / Cancel question before New, Open and Quit lose unsaved edits.

#include "core/io/Project.h"
#include "ui/InputHistory.h"
#include "ui/MainWindow.h"

#include <QAction>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QPushButton>
#include <QUndoStack>

#include <nlohmann/json.hpp>

namespace kinstab::ui {

void MainWindow::buildEditMenu() {
    m_undo = new InputHistory(
        [this] { return inputsValid() ? projectToJson(project()).dump() : std::string(); },
        [this](const std::string& s) {
            const Project p = parseProject(s);
            // Undo of "Use in project": the project's study goes; the tab keeps what it shows.
            m_project.study = p.study;
            if (projectUnits(p) != m_units) showUnits(projectUnits(p));
            showInputs(p);
        },
        this);
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = m_undo->stack()->createUndoAction(this, tr("&Undo"));
    undo->setShortcuts(QKeySequence::Undo);
    QAction* redo = m_undo->stack()->createRedoAction(this, tr("&Redo"));
    redo->setShortcuts(
        {QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_Z), QKeySequence(Qt::CTRL | Qt::Key_Y)});
    edit->addAction(undo);
    edit->addAction(redo);
    addAction(undo); // with the menu bar hidden (presentation) the keys still work
    addAction(redo);
    connect(m_undo->stack(), &QUndoStack::cleanChanged, this,
            [this](bool clean) { setWindowModified(!clean); });
    m_undo->claimUndoKeys(this);
}

MainWindow::Unsaved MainWindow::askToSave(bool canKeep) {
    if (!m_undo->isModified()) return Unsaved::Proceed;
    QMessageBox box(
        QMessageBox::Question, tr("Unsaved changes"),
        tr("Save the changes to %1?")
            .arg(m_path.isEmpty() ? tr("the untitled project") : QFileInfo(m_path).fileName()),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, this);
    box.setObjectName(QStringLiteral("unsavedChangesBox")); // tests find it by name
    box.setInformativeText(tr("Discard: the next start opens the file as last saved."));
    QPushButton* keep = nullptr;
    if (canKeep) {
        keep = box.addButton(tr("Keep for next start"), QMessageBox::ActionRole);
        keep->setToolTip(tr("Quit without saving; the next start shows these inputs again, "
                            "marked unsaved"));
    }
    box.setDefaultButton(QMessageBox::Save);
    box.exec();
    if (keep && box.clickedButton() == keep) return Unsaved::Keep;
    switch (box.standardButton(box.clickedButton())) {
    case QMessageBox::Save:
        return save() ? Unsaved::Proceed : Unsaved::Cancel;
    case QMessageBox::Discard:
        return Unsaved::Proceed;
    default:
        return Unsaved::Cancel; // Cancel, Esc or the window's close button
    }
}

} // namespace kinstab::ui
