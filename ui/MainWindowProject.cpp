// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow, continued: the project (New/Open/Save/Save As, recent files), the code ratios
// that follow the building, and what QSettings keeps between sessions.

#include "core/base/InputLimits.h"
#include "core/codes/CodeSet.h"
#include "report/CodeStyle.h"
#include "ui/AtomicSave.h"
#include "ui/BuildingPanel.h"
#include "ui/CodesPanel.h"
#include "ui/ExcitationPanel.h"
#include "ui/FloorsView.h"
#include "ui/FrictionPanel.h"
#include "ui/GridPanel.h"
#include "ui/InputHistory.h"
#include "ui/MainWindow.h"
#include "ui/ModelPanel.h"
#include "ui/ProjectFolder.h"
#include "ui/RecentFiles.h"
#include "ui/RecordsTab.h"
#include "ui/ScreenFit.h"
#include "ui/SlabPanel.h"
#include "ui/StudyTab.h"
#include "ui/SurfaceView.h"
#include "ui/TabDocks.h"
#include "ui/VerdictPanel.h"
#include "ui/teaching/TeachingView.h"

#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>

namespace kinstab::ui {

namespace {
constexpr double inch = 0.0254;
// The inputs the user chose to keep unsaved at Quit (absent: none).
const QString keptInputsKey = QStringLiteral("project/keptInputs");
const QString savedPathKey = QStringLiteral("project/path"); // the file as last saved
const QString examplePath = QStringLiteral(":/examples/paper-16-story.json");

} // namespace

Project MainWindow::project() const {
    Project p = m_project;
    p.building = m_building->building();
    p.codes = m_codesPanel->codes();
    p.slab = currentCase();
    const auto d = m_slabPanel->wallWidthMetres();
    p.wallWidthIn = d ? std::optional<double>(*d / inch) : std::nullopt;
    p.grid = m_gridPanel->grid();
    p.model = m_modelPanel->model();
    p.planar = m_modelPanel->settings();
    p.record = m_excitation->record();
    // The unit system is the project's once it names one or differs from its building's.
    Project plain = p;
    plain.units.reset();
    if (p.units || m_units != projectUnits(plain)) p.units = m_units;
    return p;
}

void MainWindow::setUnits(UnitSystem s) {
    m_units = s;
    m_teaching->setUnitSystem(s);
    m_floors->setUnitSystem(s);
    m_friction->setUnitSystem(s);
    m_slabPanel->updateDerived();
}

void MainWindow::showUnits(UnitSystem s) {
    showUnitSystem(this, s);
    applyUnitSystem(this, s);
    setUnits(s);
}

void MainWindow::showProject(const Project& p) {
    clearResults(); // no result of the previous project may stand under this one's title
    m_project = p;
    showStudy(p.study); // none: the Study tab is cleared, as the other results are
    // The project opens in its own units (the paper's in ft and in), as its report prints them.
    showUnits(projectUnits(p));
    showInputs(p);
    m_records->showProject(p); // the project's record, or an empty state
    m_undo->reset();           // a fresh start: nothing to undo, nothing unsaved
    m_undo->markSaved();
}

void MainWindow::showInputs(const Project& p) {
    m_building->setBuilding(p.building);
    m_codesPanel->setCodes(p.codes);
    m_slabPanel->load(p.slab,
                      p.wallWidthIn ? std::optional<double>(*p.wallWidthIn * inch) : std::nullopt);
    m_excitation->setEnvelope(p.slab.envelope);
    m_excitation->setScale(p.slab.scale);
    m_excitation->setTstar(p.slab.tstar);
    m_modelPanel->load(p.model, p.planar);
    m_excitation->setRecord(p.record);
    if (!m_gridPanel->setGrid(p.grid))
        statusBar()->showMessage(
            tr("The project's grid was not evenly spaced: shown as from/to/step"), 8000);
    updateCodes();
    updateRunState();
    updateTitle();
    inputsChanged();
}

void MainWindow::showStudy(const std::optional<ProjectStudy>& s) {
    m_project.study = s;
    m_study->showProjectStudy(s, m_path.isEmpty() ? QString() : QFileInfo(m_path).absolutePath());
}

void MainWindow::updateCodes() {
    m_codeResults.clear();
    m_overlays.codes.clear();
    m_overlays.buildingFrequency.reset();
    if (m_building->isValid() && m_codesPanel->isValid()) {
        const Building b = m_building->building();
        try {
            m_codeResults = runCodes(b, m_codesPanel->codes());
            m_verdict->setCodeResults(m_codeResults);
        } catch (const std::exception& e) {
            m_verdict->setError(QString::fromStdString(e.what()));
        }
        for (const CodeResult& r : m_codeResults)
            m_overlays.codes.push_back(
                {report::shortCodeName(r.code), r.topRatio, report::codeColour(r.code)});
        // The building's frequency: the entered period, else the first code's estimate.
        if (b.period)
            m_overlays.buildingFrequency = 1.0 / *b.period;
        else if (!m_codeResults.empty())
            m_overlays.buildingFrequency = 1.0 / m_codeResults.front().periodSeconds;
    }
    refreshOverlays();
}

void MainWindow::updateTitle() {
    setOpenProjectPath(m_path); // where the views' Open and Export dialogs start
    // [*]: Qt shows the modified mark there (setWindowModified).
    const QString name = !m_path.isEmpty()        ? QFileInfo(m_path).fileName()
                         : !m_shownName.isEmpty() ? m_shownName
                                                  : tr("untitled");
    setWindowTitle(m_modelPanel->isPlanar() ? tr("%1[*] — planar model — kinstab").arg(name)
                                            : tr("%1[*] — kinstab").arg(name));
}

void MainWindow::newProject() {
    Project p;
    p.codes.ubc1976 = Ubc1976Inputs{};
    p.codes.atc306 = Atc306Inputs{};
    p.wallWidthIn = 7.625;
    p.grid = GridPanel().grid();
    m_path.clear();
    m_shownName.clear();
    showProject(p);
}

bool MainWindow::openProject(const QString& path, bool quiet) {
    QFile f(path);
    try {
        if (!f.open(QIODevice::ReadOnly)) throw ProjectError(f.errorString().toStdString());
        // Bounded like core's loadProject: a device or a huge file must not eat the memory.
        const auto limit = static_cast<qint64>(limits::kMaxProjectFileBytes);
        const QByteArray text = f.read(limit + 1);
        if (text.size() > limit)
            throw ProjectError("larger than the project file limit of " +
                               std::to_string(limits::kMaxProjectFileBytes) + " bytes");
        // A record's file is stored relative to the project's directory.
        const QString dir =
            path.startsWith(QLatin1Char(':')) ? QString() : QFileInfo(path).absolutePath();
        const Project p = parseProject(text.toStdString(), dir.toStdString());
        const bool builtIn = path.startsWith(QLatin1Char(':'));
        m_path = builtIn ? QString() : path;
        // A built-in example is titled by its name; Save asks where (it is no file to write).
        m_shownName = builtIn ? tr("%1 (example)").arg(QFileInfo(path).fileName()) : QString();
        showProject(p);
        if (!m_path.isEmpty()) m_recent->add(m_path);
        statusBar()->showMessage(tr("Opened %1").arg(path), 5000);
        return true;
    } catch (const std::exception& e) {
        if (!quiet)
            QMessageBox::warning(this, tr("Open project"),
                                 tr("%1:\n%2").arg(path, QString::fromStdString(e.what())));
        return false;
    }
}

void MainWindow::openDialog() {
    if (askToSave() == Unsaved::Cancel) return;
    const QString path =
        QFileDialog::getOpenFileName(this, tr("Open project"), inProjectFolder(m_path),
                                     tr("kinstab projects (*.json);;All files (*)"));
    if (!path.isEmpty()) openProject(path);
}

QString MainWindow::saveProjectAs(const QString& path) {
    if (!inputsValid()) return tr("fix the marked inputs first");
    const Project p = project();
    if (const std::string e = validateProject(p); !e.empty()) return QString::fromStdString(e);
    // Arranged like the file that was read: a save changes only what changed.
    const std::string text = projectText(p, QFileInfo(path).absolutePath().toStdString());
    // Atomic: the old file stays until the new one is complete (ui/AtomicSave.h).
    if (const QString e = saveAtomically(path, QByteArray::fromStdString(text)); !e.isEmpty())
        return e;
    m_project = p;
    m_project.layout = nlohmann::ordered_json::parse(text);
    m_path = path;
    m_recent->add(path);
    m_undo->markSaved();
    updateTitle();
    return {};
}

bool MainWindow::save() {
    if (m_path.isEmpty()) return saveAsDialog();
    const QString e = saveProjectAs(m_path);
    if (!e.isEmpty())
        QMessageBox::warning(this, tr("Save project"), tr("%1: %2").arg(m_path, e));
    else
        statusBar()->showMessage(tr("Saved %1").arg(m_path), 5000);
    return e.isEmpty();
}

bool MainWindow::saveAsDialog() {
    QString path = QFileDialog::getSaveFileName(
        this, tr("Save project"),
        m_path.isEmpty() ? inProjectFolder(m_path, QStringLiteral("project.json")) : m_path,
        tr("kinstab projects (*.json)"));
    if (path.isEmpty()) return false;
    if (QFileInfo(path).suffix().isEmpty()) path += QStringLiteral(".json");
    m_path = path;
    return save();
}

// The next start opens the file as last saved; unsaved inputs come back only when the user
// chose "Keep for next start" at Quit, and then marked as unsaved edits.
void MainWindow::saveSettings(bool keepEdits) {
    QSettings s;
    s.setValue(QStringLiteral("window/geometry"), saveGeometry());
    m_tabDocks->giveBack(); // the charts are saved shown: a start opens on the surface
    s.setValue(QStringLiteral("window/state"), saveState());
    s.setValue(savedPathKey, m_path);
    s.remove(QStringLiteral("project/lastInputs")); // older versions kept every edit silently
    if (keepEdits && inputsValid())
        s.setValue(keptInputsKey, QString::fromStdString(projectToJson(project()).dump()));
    else
        s.remove(keptInputsKey);
}

void MainWindow::restoreSettings() {
    QSettings s;
    // A first start on a large screen: the docks were laid out at 1280 × 800 and now grow with
    // the window (laid out large and shrunk, their tabs would be cut).
    if (!restoreGeometry(s.value(QStringLiteral("window/geometry")).toByteArray()))
        resize(openingSize(screen()->availableGeometry()));
    restoreState(s.value(QStringLiteral("window/state")).toByteArray());
    // The last saved file; on the first start (or when it is gone), the paper's example.
    const QString path = s.value(savedPathKey).toString();
    if (path.isEmpty() || !openProject(path, true))
        if (!openProject(examplePath, true)) newProject();
    const QString kept = s.value(keptInputsKey).toString();
    if (kept.isEmpty()) return;
    try {
        const Project k = parseProject(kept.toStdString());
        if (k.study != m_project.study) showStudy(k.study);
        showInputs(k);
        m_undo->recordChange(); // one undoable step: the title shows them as unsaved
        statusBar()->showMessage(tr("Unsaved inputs kept from the last session"), 8000);
    } catch (const std::exception&) {
        s.remove(keptInputsKey); // unreadable: the saved file stands
    }
}

} // namespace kinstab::ui
