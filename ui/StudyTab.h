// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Study tab (docs/studies.md): a folder of records crossed with lists of mu, t* and floor
// periods; every case's critical intensity found off the GUI thread, with progress and cancel;
// then the fragility curves (fit, bootstrap bounds, empirical points), the per-record table and
// export of the rows (JSONL, as kinstab-cli study writes them) and of the fragility (JSON).
// The project's study (core/io/StudyJson.h) is shown here when a project is opened, with its
// results read back when the project names them or they lie next to it; results are marked stale
// as soon as the fields no longer describe the study they came from.

#include "core/io/StudyJson.h"
#include "core/study/Fragility.h"
#include "core/study/StudyRecordMetrics.h"
#include "core/sweep/SweepControl.h"

#include <nlohmann/json.hpp>

#include "ui/BackgroundJob.h"

#include <QStringList>
#include <QWidget>

#include <functional>
#include <memory>
#include <optional>
#include <string>

class QChartView;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QTableWidget;
class QTabWidget;

namespace kinstab::ui {

class RiskPanel;
struct StudyOutcome; // what a job hands back (ui/StudyTabOutcome.h)

class StudyTab : public QWidget {
    Q_OBJECT
public:
    explicit StudyTab(QWidget* parent = nullptr);
    ~StudyTab() override;

    // The fields, for tests and for a study opened from a file.
    void setRecordsFolder(const QString& folder, const QString& include, const QString& exclude);
    void setLists(const QString& mu, const QString& tstar, const QString& floorPeriods);
    void setSearch(double maxG, double scanStepG);
    // The study file text the fields describe (kinstab-study, version 1); settings the fields
    // do not show (search tolerance, floor dampings, the ground case) are kept from the study
    // file opened last.
    std::string studyJson() const;
    // Fills the fields from a study file; false, with the reason in message(), when it cannot be
    // read or its records are not all in one folder (the tab shows one folder).
    bool openStudy(const QString& path);
    // Makes the study the project's (signal studyChosen): the file opened last, unless the
    // fields were run or edited since, in which case they are written to savePath first. Results
    // that are current go with it: their file, or the rows of the run written next to the study
    // file as NAME.jsonl; stale results do not (the report then runs the study).
    bool useInProject(const QString& savePath);
    QString studyFile() const { return m_studyFile; }

    // The project's study, shown when a project is opened (none: the tab is cleared). Its
    // results are read off the GUI thread (signal finished) from study.results, else from
    // NAME.jsonl beside the project or the study file; rows of another study are not shown.
    void showProjectStudy(const std::optional<ProjectStudy>& study, const QString& projectDir);
    // Back to a new tab: default fields, no study file, no results; a running study is dropped.
    void clear();
    QString resultsFile() const { return m_resultsFile; } // the file the results came from
    // Results are shown but the fields were edited since they were made.
    bool resultsStale() const;

    void run();
    void cancel();
    bool isRunning() const;
    QString message() const;
    const std::string& rows() const { return m_rows; } // JSONL of the last finished run
    const std::vector<Fragility>& fragility() const { return m_fragility; }
    QTableWidget* table() const { return m_table; }   // one row per case
    QTableWidget* setTable() const { return m_sets; } // one row per parameter set
    QChartView* chartView() const { return m_chart; }
    RiskPanel* riskPanel() const { return m_risk; } // the results on the site's hazard curve
    bool exportRows(const QString& path);           // false, with the reason in message()
    bool exportFragility(const QString& path);      // JSON

signals:
    void finished();
    void studyChosen(const QString& specPath, const QString& resultsPath);

private:
    void showBlockStudy(bool block);
    QLayout* buildFileRow();
    QLayout* buildForm();
    QLayout* buildRunBar();
    QWidget* buildResults();
    void connectFields();
    void onDelivered(const StudyOutcome& o);
    void fillTable();
    void showResults(const StudyOutcome& o);
    void updateStaleness();
    void startJob(std::function<StudyOutcome(JobContext&)> job, const QString& status);
    QString currentResultsFile(); // "" when none is current; writes the run's rows if need be
    bool save(const QString& path, const std::string& text); // false: the reason in message()

    QLineEdit* m_folder;
    QLineEdit* m_include;
    QLineEdit* m_exclude;
    QComboBox* m_measure;
    QDoubleSpinBox* m_saPeriod;
    QLineEdit* m_mu;
    QLineEdit* m_tstar;
    QLineEdit* m_floors;
    QDoubleSpinBox* m_maxG;
    QDoubleSpinBox* m_step;
    QPushButton* m_run;
    QPushButton* m_cancel;
    QPushButton* m_export;
    QProgressBar* m_progress;
    QLabel* m_status;
    QLabel* m_stale; // "results are for the previous parameters — run again"
    QChartView* m_chart;
    RiskPanel* m_risk;
    QTableWidget* m_sets;
    QTableWidget* m_table;
    BackgroundJob m_job; // the run, or the results read back: one at a time
    std::string m_rows;
    std::vector<StudyRow> m_parsed;
    std::vector<Fragility> m_fragility;
    std::vector<StudyRecordMetrics> m_metrics; // the suite's records, for the case table
    std::string m_resultsSpec; // studyJson() of the fields the shown results are for
    QString m_resultsFile;     // the file they were read from ("" after a run)
    nlohmann::json m_base = nlohmann::json::object(); // the study file opened last
    QString m_studyFile;                              // its path; empty: none opened
    std::string m_openedText;                         // studyJson() right after opening
    // The opened file's records, one absolute file each in the file's order, used while the
    // record fields still show what opening put there (a folder pattern would sort them).
    nlohmann::json m_openedRecords;
    QStringList m_openedRecordFields; // folder, include, exclude as opening set them
};

} // namespace kinstab::ui
