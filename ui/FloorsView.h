// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Floors view (issue 19): the project's building as a shear building under a ground record.
// Left, the height profile of the peak floor acceleration (the model's for the record, the
// paper's SDOF filter at the roof, ASCE 7-22 §13.3.1 and EN 1998-1 §4.3.5.2 demands); right,
// the critical PGA per level; below, a picked level's motion and the slab's run under it, and
// the verdicts at the slab's level. The analysis runs off the GUI thread and can be cancelled.

#include "core/building/FloorAnalysis.h"
#include "core/io/Project.h"
#include "ui/BackgroundJob.h"
#include "ui/Units.h"

#include <QWidget>

#include <functional>
#include <memory>

class QChartView;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLayout;
class QLineEdit;
class QPushButton;
class QSpinBox;

namespace kinstab::ui {

class FloorsView : public QWidget {
    Q_OBJECT
public:
    // source: the project as the main window's panels describe it, read at each run.
    explicit FloorsView(std::function<Project()> source, QWidget* parent = nullptr);
    ~FloorsView() override;

    void setRecordPath(const QString& path); // ":/records/..." or a file
    void run();
    void cancel();
    bool isRunning() const;
    void pickLevel(int level);        // 1-based
    void setUnitSystem(UnitSystem s); // the height axes in m or ft (View → Units)
    QString message() const;          // the last error or status line
    QChartView* profileView() const { return m_profile; }
    QChartView* criticalView() const { return m_critical; }
    QChartView* levelView() const { return m_level; }

signals:
    void analysisShown();

protected:
    void showEvent(QShowEvent* e) override;

private:
    void setUpFields();
    QLayout* buildRecordBar();
    struct Outcome;
    void applyProject(const Project& p);
    void onFinished(std::shared_ptr<Outcome> o);
    void showVerdicts();
    void drawHeightCharts();

    std::function<Project()> m_source;
    QLineEdit* m_record;
    QComboBox* m_stiffness;
    QDoubleSpinBox* m_damping;
    QSpinBox* m_slabLevel;
    QPushButton* m_run;
    QPushButton* m_cancel;
    QSpinBox* m_pick;
    QLabel* m_status;
    QLabel* m_verdicts;
    QChartView* m_profile;
    QChartView* m_critical;
    QChartView* m_level;
    BackgroundJob m_job;
    std::shared_ptr<Outcome> m_shown;
    UnitSystem m_units = UnitSystem::SI;
    std::string m_appliedRecord; // the project's record file last applied to the fields
    std::string m_appliedFloors; // and its floors settings (JSON text)
};

} // namespace kinstab::ui
