// SPDX-License-Identifier: GPL-3.0-or-later
// MainWindow (ui/MainWindow.h): its construction, the centre's tabs, the inputs' wiring, the first
// show and the close. The rest, one concern a file: MainWindowMenus (File, Sweep), MainWindowEdits
// (Edit, unsaved changes), MainWindowDocks, MainWindowSweep (the run), MainWindowExport,
// MainWindowProject (files, settings), MainWindowResults, MainWindowRecord, MainWindowPlanar,
// MainWindowBlock. This file and MainWindow.h together pass 400 lines: the header declares the
// one window class whole, with the accessors the tests use.
#include "ui/MainWindow.h"

#include "ui/BlockMapView.h"
#include "ui/BuildingPanel.h"
#include "ui/ChartMenu.h"
#include "ui/CodesPanel.h"
#include "ui/CriticalChart.h"
#include "ui/ExcitationPanel.h"
#include "ui/FloorsView.h"
#include "ui/FrictionPanel.h"
#include "ui/GridPanel.h"
#include "ui/HelpMenu.h"
#include "ui/HistoryChart.h"
#include "ui/InputHistory.h"
#include "ui/ModelPanel.h"
#include "ui/NumericsView.h"
#include "ui/PlanarHistoryChart.h"
#include "ui/RecordPreview.h"
#include "ui/RecordsTab.h"
#include "ui/RunProgress.h"
#include "ui/ScreenFit.h"
#include "ui/Scrollable.h"
#include "ui/SlabPanel.h"
#include "ui/SliceChart.h"
#include "ui/StudyTab.h"
#include "ui/SurfaceView.h"
#include "ui/UnitsMenu.h"
#include "ui/VerdictPanel.h"
#include "ui/teaching/PresentationMode.h"
#include "ui/teaching/TeachingView.h"

#include <QAction>
#include <QCloseEvent>
#include <QLabel>
#include <QMenu>
#include <QPainter>
#include <QRegularExpression>
#include <QStatusBar>
#include <QTabWidget>
#include <QTimer>

namespace kinstab::ui {

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
