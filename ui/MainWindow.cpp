// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/MainWindow.h"

#include "ui/AtomicSave.h"
#include "ui/BlockMapView.h"
#include "ui/ChartMenu.h"
#include "ui/FloorsView.h"
#include "ui/FrictionPanel.h"
#include "ui/NumericsView.h"
#include "ui/RecordPreview.h"
#include "ui/RecordsTab.h"
#include "ui/StudyTab.h"

#include "core/codes/CodeSet.h"
#include "core/io/JsonText.h"
#include "core/io/ResultJson.h"
#include "core/io/SurfaceJson.h"
#include "ui/BuildingPanel.h"
#include "ui/ChartExport.h"
#include "ui/CodesPanel.h"
#include "ui/CriticalChart.h"
#include "ui/ExampleProjects.h"
#include "ui/ExcitationPanel.h"
#include "ui/GridPanel.h"
#include "ui/HelpMenu.h"
#include "ui/HistoryChart.h"
#include "ui/InputHistory.h"
#include "ui/ModelPanel.h"
#include "ui/PlanarHistoryChart.h"
#include "ui/ProjectFolder.h"
#include "ui/ProjectInfoPanel.h"
#include "ui/RecentFiles.h"
#include "ui/ReportExport.h"
#include "ui/RunProgress.h"
#include "ui/ScreenFit.h"
#include "ui/SlabPanel.h"
#include "ui/SliceChart.h"
#include "ui/StaleFrame.h"
#include "ui/SurfaceView.h"
#include "ui/TabDocks.h"
#include "ui/UnitsMenu.h"
#include "ui/VerdictPanel.h"
#include "ui/teaching/PresentationMode.h"
#include "ui/teaching/TeachingView.h"

#include <QAction>
#include <QCloseEvent>
#include <QDir>
#include <QDockWidget>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QPainter>
#include <QRegularExpression>
#include <QScrollArea>
#include <QSettings>
#include <QStackedWidget>
#include <QStatusBar>
#include <QTabWidget>
#include <QTimer>
#include <QToolBar>

#include <cmath>

#include <nlohmann/json.hpp>

namespace kinstab::ui {

namespace {
QWidget* scrollable(QWidget* w) {
    auto* s = new QScrollArea;
    s->setWidget(w);
    s->setWidgetResizable(true);
    s->setFrameShape(QFrame::NoFrame);
    return s;
}
} // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), m_building(new BuildingPanel), m_codesPanel(new CodesPanel),
      m_slabPanel(new SlabPanel), m_excitation(new ExcitationPanel), m_gridPanel(new GridPanel),
      m_surface(new SurfaceView), m_slice(new SliceChart), m_history(new HistoryChart),
      m_critical(new CriticalChart), m_verdict(new VerdictPanel), m_runner(new SweepRunner(this)),
      m_progress(new RunProgress), m_status(new QLabel) {
    m_modelPanel = new ModelPanel;
    m_planarHistory = new PlanarHistoryChart;
    m_assessJob = new BackgroundJob(this);
    setWindowTitle(tr("kinstab — kinetic stability of friction-held slabs"));
    setDockOptions(QMainWindow::AnimatedDocks | QMainWindow::AllowTabbedDocks |
                   QMainWindow::AllowNestedDocks);
    buildCentre();
    buildActions();
    installHelpMenu(this);
    installChartMenus(); // right-click Save image… / Copy image on every chart
    buildDocks();
    installPresentationMode(this, m_viewMenu, m_centre, m_teaching);
    installUnitsMenu(m_viewMenu, this, [this](UnitSystem s) { setUnits(s); });
    buildStatusBar();
    connectInputs();
    connectRuns();
    // 1280 × 800, or less on a smaller screen (more once the docks are laid out, in
    // restoreSettings); the frame is fitted at the first show.
    resize(sizeInside({1280, 800}, screen()->availableGeometry(), {}));
    arrangeDocks();
    buildTabDocks();
    restoreSettings();
    m_records->preview()->setPlanarBase(m_modelPanel->isPlanar());
    updateRunState();
    updateTitle();
}

// The result chart docks give their room to the tabs that do not show them.
void MainWindow::buildTabDocks() {
    m_tabDocks = new TabDocks(
        m_centre, m_chartDocks,
        [this](int i) {
            // The first tab holds the surface (or the block's map) in a stack.
            return m_centre->widget(i)->isAncestorOf(m_surface) ||
                   m_centre->widget(i)->isAncestorOf(m_records);
        },
        this);
}

// The γc surface and the other tabs share the centre.
void MainWindow::buildCentre() {
    m_centre = new QTabWidget;
    m_centre->setDocumentMode(true);
    m_centre->addTab(buildBlockMap(), tr("γc surface"));
    m_teaching = new TeachingView;
    m_centre->addTab(scrollable(buildTeachingStack()),
                     tr("Teaching")); // its minimum size must not grow the window
    m_records = new RecordsTab;
    m_centre->addTab(scrollable(m_records), tr("Records"));
    m_numerics = new NumericsView;
    m_centre->addTab(m_numerics, tr("Numerics"));
    m_friction = new FrictionPanel;
    // In scroll areas: their minimum sizes must not grow the window past 1280×800.
    m_centre->addTab(scrollable(m_friction), tr("Friction"));
    m_floors = new FloorsView([this] { return project(); });
    m_centre->addTab(scrollable(m_floors), tr("Floors"));
    m_study = new StudyTab;
    m_centre->addTab(scrollable(m_study), tr("Study"));
    connect(m_study, &StudyTab::studyChosen, this,
            [this](const QString& spec, const QString& results) {
                // No results: the report runs the study. An undoable, unsaved change. The
                // hazard curve is the site's, not the study's: it stays.
                std::optional<ProjectHazard> hazard;
                if (m_project.study) hazard = m_project.study->hazard;
                m_project.study = ProjectStudy{spec.toStdString(), results.toStdString(), hazard};
                m_undo->recordChange();
                statusBar()->showMessage(tr("The project's study is %1; save to keep it").arg(spec),
                                         5000);
            });
    setCentralWidget(m_centre);
}

void MainWindow::buildStatusBar() {
    m_status->setTextFormat(Qt::PlainText);
    statusBar()->addWidget(m_status, 1);
    statusBar()->addPermanentWidget(m_progress);
}

// Every input panel's change re-gates Run, re-judges the results and is an undo step.
void MainWindow::connectInputs() {
    const std::initializer_list<InputPanel*> all{m_building,   m_codesPanel, m_slabPanel,
                                                 m_modelPanel, m_excitation, m_gridPanel};
    for (InputPanel* p : all)
        connect(p, &InputPanel::changed, this, &MainWindow::updateRunState);
    for (InputPanel* p : std::initializer_list<InputPanel*>{m_building, m_codesPanel})
        connect(p, &InputPanel::changed, this, &MainWindow::updateCodes);
    // After updateCodes: results are judged against the code ratios of the new inputs.
    for (InputPanel* p : all) {
        connect(p, &InputPanel::changed, this, &MainWindow::inputsChanged);
        connect(p, &InputPanel::changed, m_undo, &InputHistory::recordChange);
    }
    connect(m_modelPanel, &InputPanel::changed, this, &MainWindow::updateTitle);
    connect(m_modelPanel, &InputPanel::changed, this, &MainWindow::showModelView);
    connect(m_modelPanel, &InputPanel::changed, this,
            [this] { m_records->preview()->setPlanarBase(m_modelPanel->isPlanar()); });
    connect(m_slabPanel, &InputPanel::changed, this, [this] {
        if (m_slabPanel->isValid()) m_excitation->setTstar(currentCase().tstar);
    });
    // "Use this mu" from the friction calibration goes to the slab's friction field.
    connect(m_friction, &FrictionPanel::useMu, m_slabPanel, &SlabPanel::useMu);
    // A switch of units is an input step (after the switch, connected in installUnitsMenu): the
    // project file keeps its units, so undo restores them.
    for (QAction* a : m_viewMenu->findChildren<QAction*>(QRegularExpression("^units(SI|US)$")))
        connect(a, &QAction::triggered, m_undo, &InputHistory::recordChange);
}

// The sweep's progress and result, the record's run, and picking a point of the surface.
void MainWindow::connectRuns() {
    connect(m_runner, &SweepRunner::progress, this, &MainWindow::showProgress);
    connect(m_runner, &SweepRunner::partialResult, this, &MainWindow::showPartial);
    connect(m_runner, &SweepRunner::finished, this, &MainWindow::showFinished);
    buildRecordRun();
    connect(m_surface, &SurfaceView::pointSelected, this, &MainWindow::pickPoint);
}

MainWindow::~MainWindow() {
    // The runner (a child) cancels and waits in its destructor; do it before the views go.
    m_runner->cancel();
    m_blockMap->cancel();
}

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
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);
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

QDockWidget* MainWindow::addPanelDock(const QString& title, QWidget* w, Qt::DockWidgetArea area) {
    auto* dock = new QDockWidget(title, this);
    dock->setObjectName(
        title.simplified().remove(QLatin1Char('&')).replace(QLatin1Char(' '), QLatin1Char('_')) +
        "Dock");
    dock->setWidget(w);
    addDockWidget(area, dock);
    m_viewMenu->addAction(dock->toggleViewAction());
    return dock;
}

void MainWindow::buildDocks() {
    // Short titles: six tabs share the inputs' dock and must not be cut at 1280 px.
    const std::pair<QString, QWidget*> inputs[] = {
        {tr("Building"), m_building}, {tr("Codes"), m_codesPanel},  {tr("Slab"), m_slabPanel},
        {tr("Model"), m_modelPanel},  {tr("Motion"), m_excitation}, {tr("Grid"), m_gridPanel}};
    for (const auto& [title, w] : inputs)
        m_inputDocks.push_back(addPanelDock(title, scrollable(w), Qt::LeftDockWidgetArea));
    m_verdictFrame = new StaleFrame(m_verdict);
    m_verdictDock = addPanelDock(tr("Verdict"), m_verdictFrame, Qt::LeftDockWidgetArea);
    m_sliceFrame = new StaleFrame(m_slice);
    m_historyStack = new QStackedWidget;
    m_historyStack->addWidget(m_history);
    m_historyStack->addWidget(m_planarHistory);
    m_historyFrame = new StaleFrame(m_historyStack);
    m_criticalFrame = new StaleFrame(m_critical);
    m_chartDocks = {addPanelDock(tr("γc, τc against A"), m_sliceFrame, Qt::BottomDockWidgetArea),
                    addPanelDock(tr("History"), m_historyFrame, Qt::BottomDockWidgetArea),
                    addPanelDock(tr("A_crit(f)"), m_criticalFrame, Qt::BottomDockWidgetArea)};
    m_viewMenu->addSeparator();
    m_viewMenu->addAction(tr("Reset &layout"), this, &MainWindow::resetLayout);
}

// The inputs tabbed on the left above the verdict; the three charts side by side along the
// bottom, below the surface only (the left column runs the full height), with a third of it.
void MainWindow::arrangeDocks() {
    setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
    for (QDockWidget* d : m_inputDocks)
        addDockWidget(Qt::LeftDockWidgetArea, d);
    addDockWidget(Qt::LeftDockWidgetArea, m_verdictDock);
    splitDockWidget(m_inputDocks.front(), m_verdictDock, Qt::Vertical);
    for (std::size_t i = 1; i < m_inputDocks.size(); ++i)
        tabifyDockWidget(m_inputDocks.front(), m_inputDocks[i]);
    for (QDockWidget* d : m_chartDocks)
        addDockWidget(Qt::BottomDockWidgetArea, d);
    splitDockWidget(m_chartDocks[0], m_chartDocks[1], Qt::Horizontal);
    splitDockWidget(m_chartDocks[1], m_chartDocks[2], Qt::Horizontal);
    std::vector<QDockWidget*> all = m_inputDocks;
    all.push_back(m_verdictDock);
    all.insert(all.end(), m_chartDocks.begin(), m_chartDocks.end());
    for (QDockWidget* d : all) {
        d->setFloating(false);
        d->show();
    }
    m_inputDocks.front()->raise();
    const int h = height();
    resizeDocks({m_inputDocks.front(), m_verdictDock}, {h * 55 / 100, h * 45 / 100}, Qt::Vertical);
    resizeDocks({m_inputDocks.front()}, {std::max(430, width() * 30 / 100)}, Qt::Horizontal);
    resizeDocks({m_chartDocks.front()}, {std::max(240, h * 34 / 100)}, Qt::Vertical);
    const int w = std::max(300, (width() - 430) / 3);
    resizeDocks({m_chartDocks[0], m_chartDocks[1], m_chartDocks[2]}, {w, w, w}, Qt::Horizontal);
}

void MainWindow::resetLayout() {
    arrangeDocks();
}

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
    m_results.startSweep(job->slab, job->planar);
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
    GammaGrid g = gammaGrid(r, s.slabCase.tauRef()); // the planar case's too
    g.gammaTitle = QString::fromStdString(gammaScaleLabel(s.slabCase.scale)) + modelTitle();
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
        teachingParamsOf(s->slabCase, s->planarCase(), a, f, m_teaching->params(), &notShown));
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

void MainWindow::exportSurface() {
    if (!m_results.surface() || m_results.surface()->gamma.empty()) {
        m_status->setText(tr("Nothing to export: run a sweep first"));
        return;
    }
    const SweepResult& sweep = m_results.surface()->sweep; // with the inputs it was run with
    const Slab1DCase& sweepCase = m_results.surface()->slabCase;
    const std::optional<PlanarCase> sweepPlanar = m_results.surface()->planarCase();
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

QImage MainWindow::screenshot() {
    QImage img = grab().toImage();
    // The 3D view's own image where it is on screen; not over another tab that hides it.
    if (m_surface->showsGL() && m_surface->graphWidget()->isVisible()) {
        QWidget* c = m_surface->graphWidget();
        const QRect target(c->mapTo(this, QPoint(0, 0)), c->size());
        const QImage graph = m_surface->renderImage(c->size() * img.devicePixelRatio());
        QPainter p(&img);
        p.drawImage(target, graph);
    }
    return img;
}

void MainWindow::showEvent(QShowEvent* e) {
    QMainWindow::showEvent(e);
    if (m_fittedSize.isValid()) return; // only the first show: later the user placed it
    fitToScreen(this, size());
    m_fittedSize = size();
    // On X11 the window manager frames the window after it is mapped, so its title bar is
    // known only then: fit again, unless someone chose a size in between.
    QTimer::singleShot(400, this, [this] {
        if (size() != m_fittedSize) return;
        fitToScreen(this, size());
        m_fittedSize = size();
    });
}

void MainWindow::closeEvent(QCloseEvent* e) {
    const Unsaved choice = askToSave(true);
    if (choice == Unsaved::Cancel) return e->ignore();
    m_runner->cancel();
    saveSettings(choice == Unsaved::Keep);
    e->accept();
}

} // namespace kinstab::ui
