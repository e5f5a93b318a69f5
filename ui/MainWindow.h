// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The main window: input panels and the verdict in docks on the left, the γc surface in the
// middle, the linked charts in docks below. Run/Cancel drive a SweepRunner.

#include "core/assessment/Assessment.h"
#include "core/io/Project.h"
#include "core/slab/Slab1DCase.h"
#include "ui/BackgroundJob.h"
#include "ui/PlanarPointRun.h"
#include "ui/PointRun.h"
#include "ui/RecordRunner.h"
#include "ui/ResultState.h"
#include "ui/SurfaceData.h"
#include "ui/SweepRunner.h"
#include "ui/Units.h"

#include <QMainWindow>

#include <optional>

class QAction;
class QChartView;
class QComboBox;
class QDockWidget;
class QLabel;
class QStackedWidget;
class QTabWidget;

namespace kinstab::ui {

class BlockMapView;
class BlockTeachingView;
class BuildingPanel;
class TabDocks;
class CodesPanel;
class CriticalChart;
class RecentFiles;
class RunProgress;
class VerdictPanel;
class ExcitationPanel;
class GridPanel;
class HistoryChart;
class InputHistory;
class ModelPanel;
class PlanarHistoryChart;
class SlabPanel;
class SliceChart;
class SurfaceView;
class TeachingView;
class RecordsTab;
class NumericsView;
class FrictionPanel;
class FloorsView;
class StaleFrame;
class StudyTab;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // The 1-DOF case the panels describe (valid panels only).
    Slab1DCase currentCase() const;
    // Everything the panels describe, with what they do not show kept from the open project.
    Project project() const;
    void showProject(const Project& p);
    // Opens a project file; false (with a message box unless quiet) when it cannot be read.
    bool openProject(const QString& path, bool quiet = false);
    // Writes the project atomically (ui/AtomicSave.h); empty on success, else the reason.
    QString saveProjectAs(const QString& path);
    bool inputsValid() const;
    // The window as an image, with the 3D view rendered in (grab() leaves a GL window blank).
    QImage screenshot();
    // Adds a dock (friction, records, precision, teaching...) tabified with its peers.
    QDockWidget* addPanelDock(const QString& title, QWidget* w, Qt::DockWidgetArea area);

    // For tests and scripting.
    QAction* runAction() const { return m_run; }
    QAction* cancelAction() const { return m_cancel; }
    SweepRunner* runner() const { return m_runner; }
    SurfaceView* surfaceView() const { return m_surface; }
    // The free-standing block's overturning map (the first tab while that model is chosen).
    BlockMapView* blockMapView() const { return m_blockMap; }
    HistoryChart* historyChart() const { return m_history; }
    SliceChart* sliceChart() const { return m_slice; }
    SlabPanel* slabPanel() const { return m_slabPanel; }
    ModelPanel* modelPanel() const { return m_modelPanel; }
    PlanarHistoryChart* planarHistoryChart() const { return m_planarHistory; }
    // The planar case the surface was computed with (none: the 1-DOF model).
    const std::optional<PlanarCase>& sweepPlanarCase() const;
    const std::optional<PlanarPointRun>& pickedPlanarRun() const {
        return m_results.pickedPlanar();
    }
    ExcitationPanel* excitationPanel() const { return m_excitation; }
    GridPanel* gridPanel() const { return m_gridPanel; }
    BuildingPanel* buildingPanel() const { return m_building; }
    CodesPanel* codesPanel() const { return m_codesPanel; }
    VerdictPanel* verdictPanel() const { return m_verdict; }
    TeachingView* teachingView() const { return m_teaching; }
    // The Teaching tab's free-standing block, and the choice between it and the slab.
    BlockTeachingView* blockTeachingView() const { return m_blockTeaching; }
    QComboBox* teachingSubject() const { return m_teachingSubject; }
    FloorsView* floorsView() const { return m_floors; }
    FrictionPanel* frictionPanel() const { return m_friction; }
    UnitSystem unitSystem() const { return m_units; } // View → Units, or the open project's
    StudyTab* studyTab() const { return m_study; }
    const QString& projectPath() const { return m_path; }
    // Undo/redo of the inputs and the modified mark (ui/InputHistory.h).
    InputHistory* inputHistory() const { return m_undo; }
    // Every shown result with the inputs it was made with (ui/ResultState.h).
    const ResultState& results() const { return m_results; }
    const SweepResult& lastSweep() const; // empty when there is no surface
    const std::optional<PointRun>& pickedRun() const { return m_results.picked(); }
    const std::optional<DesignCheckResult>& lastCheck() const { return m_results.check(); }
    RecordRunner* recordRunner() const { return m_recordRunner; }
    // The last record run (MainWindowRecord.cpp): single run, critical scale, verdicts.
    const std::optional<RecordOutput>& lastRecordRun() const { return m_results.recordRun(); }
    // The result frames (dimmed with "inputs changed — Run to update" while stale).
    StaleFrame* sliceFrame() const { return m_sliceFrame; }
    StaleFrame* historyFrame() const { return m_historyFrame; }
    StaleFrame* criticalFrame() const { return m_criticalFrame; }
    StaleFrame* verdictFrame() const { return m_verdictFrame; }

public slots:
    void runSweep();
    void cancelSweep();
    void newProject();
    void openDialog();
    // View → Reset layout: every dock back where a first start puts it.
    void resetLayout();
    bool save();
    bool saveAsDialog();

    // The project's whole assessment (core/assessment/RunAssessment.h), as check and the report
    // give it, computed after each run; none before the first or when inputs changed since.
    const Assessment* fullAssessment() const;

signals:
    void sweepFinished();
    void recordRunFinished();
    void assessmentFinished(); // the whole assessment of the inputs shown is in the panel
    void blockMapFinished();   // a run of the block's overturning map ended (or was cancelled)

protected:
    void closeEvent(QCloseEvent* e) override;
    // The first show fits the window, frame included, into the screen (ui/ScreenFit.h).
    void showEvent(QShowEvent* e) override;

private:
    // The constructor's parts.
    void buildCentre();
    void buildStatusBar();
    void connectInputs();
    void connectRuns();
    void buildTabDocks();
    void buildActions();
    void buildFileMenu();
    void addExportActions(QMenu* file); // File → Export surface, chart, report
    // Undo/redo and the unsaved-changes guard (MainWindowEdits.cpp).
    void buildEditMenu();
    enum class Unsaved { Proceed, Keep, Cancel };
    // Asks Save / Discard / Cancel (and "Keep for next start" when canKeep) if modified.
    Unsaved askToSave(bool canKeep = false);
    void showInputs(const Project& p);                    // the panels only: no result is cleared
    void showStudy(const std::optional<ProjectStudy>& s); // the project's, in the Study tab
    void arrangeDocks();
    void updateCodes();
    void updateTitle();
    void buildDocks();
    void updateRunState();
    void showPartial(const SweepResult& r);
    void showFinished(const AnalysisResult& out);
    void showProgress(qint64 done, qint64 total);
    void pickPoint(int ai, int fi);
    void updateSlice();
    void refreshOverlays();
    // Results against the inputs now shown (MainWindowResults.cpp): New/Open clear them, an
    // input change re-judges what it can and marks the rest stale.
    void clearResults();
    void inputsChanged();
    void showStaleness();
    void showVerdict();
    Assessment currentAssessment() const;
    QString assessmentScope() const;
    void startAssessment(); // the whole assessment of the inputs shown, in the background
    void exportSurface();
    void exportChart(QChartView* view, const QString& name);
    // The planar model (MainWindowPlanar.cpp).
    // The Run's request of the project (ui/SweepRunner.h), the surface tab named for its model;
    // nullopt, with the reason in the status line, when the planar vertical cannot be read.
    std::optional<AnalysisRequest> runRequest(const Project& p);
    void pickPlanar(double amplitude, double frequency);
    QString modelTitle() const;
    void saveSettings(bool keepEdits = false);
    void restoreSettings();
    void setUnits(UnitSystem s);  // the views that draw lengths (the fields follow by themselves)
    void showUnits(UnitSystem s); // the menu's mark, the fields and the views (open, undo)
    // The free-standing block model (MainWindowBlock.cpp).
    QWidget* buildBlockMap(); // the first tab: the γc surface or the block's map
    void showModelView();
    void runBlockMap();
    QWidget* buildTeachingStack(); // the slab's or the block's animation
    // A record as the excitation (MainWindowRecord.cpp).
    void buildRecordRun();
    void runRecord();
    void showRecordFinished(const RecordOutput& out);

    BuildingPanel* m_building;
    CodesPanel* m_codesPanel;
    SlabPanel* m_slabPanel;
    ModelPanel* m_modelPanel = nullptr;
    ExcitationPanel* m_excitation;
    GridPanel* m_gridPanel;
    SurfaceView* m_surface;
    BlockMapView* m_blockMap = nullptr;
    QStackedWidget* m_resultStack = nullptr; // the γc surface or the block's map
    SliceChart* m_slice;
    HistoryChart* m_history;
    PlanarHistoryChart* m_planarHistory = nullptr;
    QStackedWidget* m_historyStack = nullptr; // the 1-DOF or the planar history
    CriticalChart* m_critical;
    VerdictPanel* m_verdict;
    QTabWidget* m_centre = nullptr;
    TeachingView* m_teaching = nullptr;
    BlockTeachingView* m_blockTeaching = nullptr;
    QComboBox* m_teachingSubject = nullptr; // in the tab bar's corner while Teaching shows
    RecordsTab* m_records = nullptr;
    NumericsView* m_numerics = nullptr;
    StudyTab* m_study = nullptr;
    FrictionPanel* m_friction = nullptr;
    FloorsView* m_floors = nullptr;
    UnitSystem m_units = UnitSystem::SI;
    RecentFiles* m_recent = nullptr;
    SweepRunner* m_runner;
    RecordRunner* m_recordRunner = nullptr;
    QAction* m_run = nullptr;
    QAction* m_cancel = nullptr;
    QMenu* m_viewMenu = nullptr;
    RunProgress* m_progress;
    QLabel* m_status;
    std::vector<QDockWidget*> m_inputDocks;
    QDockWidget* m_verdictDock = nullptr;
    std::vector<QDockWidget*> m_chartDocks; // along the bottom
    InputHistory* m_undo = nullptr;
    TabDocks* m_tabDocks = nullptr;

    Project m_project; // the open project: inputs no panel shows are kept from it
    QString m_path;
    QString m_shownName; // the title's file name: m_path's, or a built-in example's
    std::vector<CodeResult> m_codeResults;

    ResultState m_results;
    BackgroundJob* m_assessJob = nullptr;
    // The whole assessment and the inputs it was made with (shown while they are the inputs).
    std::optional<std::pair<InputFingerprint, Assessment>> m_assessment;
    SurfaceOverlays m_overlays; // code ratios and building frequency (inputs), A_crit (result)
    StaleFrame* m_sliceFrame = nullptr;
    StaleFrame* m_historyFrame = nullptr;
    StaleFrame* m_criticalFrame = nullptr;
    StaleFrame* m_verdictFrame = nullptr;
    int m_selA = -1, m_selF = -1;
    QSize m_fittedSize; // the size the first show fitted (invalid before it)
};

} // namespace kinstab::ui
