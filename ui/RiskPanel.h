// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Study tab's risk view (docs/studies.md, "Risk"): the study's results on the site's hazard
// curve - the project's (study.hazard) or one the user picks here. For the selected parameter
// set: the hazard curve, the set's fragility and the integrand of lambda_C, with the numbers
// beside them (lambda_C, the probability in N years, the target rate and margin, Cornell's first-
// and second-order forms, P(C) at a given intensity such as the MCE_R, and lambda_C's bootstrap
// percentiles). Every set is computed by core (core/risk/SetRisk.h) on a BackgroundJob.

#include "core/io/StudyJson.h"
#include "core/risk/SetRisk.h"
#include "ui/BackgroundJob.h"

#include <QWidget>

#include <optional>
#include <string>
#include <vector>

class QChartView;
class QComboBox;
class QLabel;
class QLineEdit;

namespace kinstab::ui {

struct RiskOutcome {
    HazardCurve curve;
    RiskSettings settings;
    std::vector<SetRisk> sets;
    std::string error; // the hazard file or the study's measure, named
    bool cancelled = false;
};

// Reads the hazard curve in the measure of the rows and computes every set (off the GUI thread).
RiskOutcome runRiskJob(const ProjectHazard& hazard, const std::vector<StudyRow>& rows,
                       std::optional<double> imG, SweepControl* control);

class RiskPanel : public QWidget {
    Q_OBJECT
public:
    explicit RiskPanel(QWidget* parent = nullptr);
    ~RiskPanel() override;

    // The project's hazard curve (none: the user may pick one); computed once rows are given.
    void setHazard(const std::optional<ProjectHazard>& h);
    // A curve picked here: the project's years and target rate are kept (the code's without).
    void setHazardFile(const QString& path);
    // P(C) at this intensity (g), e.g. the site's MCE_R; none: not shown.
    void setIntensityOfInterest(std::optional<double> imG);
    void setRows(const std::vector<StudyRow>& rows);
    void clear(); // no rows, no curve: a new study
    void selectSet(int index);

    bool isRunning() const { return m_job.isRunning(); }
    const std::optional<RiskOutcome>& outcome() const { return m_outcome; }
    int selectedSet() const;
    QString numbersText() const; // the numbers beside the charts, as plain text
    QString message() const;
    QChartView* hazardView() const { return m_hazardChart; }
    QChartView* fragilityView() const { return m_fragilityChart; }
    QChartView* integrandView() const { return m_integrandChart; }

signals:
    void finished(); // a computation delivered (or failed)

private:
    QLayout* buildInputs();
    QLayout* buildCharts();
    void recompute();
    void showOutcome(RiskOutcome o);
    void showSet();

    QLineEdit* m_file;
    QLineEdit* m_imOfInterest;
    QLabel* m_imError; // beside the field: why its entry is refused
    QString m_imErrorText;
    QComboBox* m_set;
    QLabel* m_status;
    QLabel* m_numbers;
    QChartView* m_hazardChart;
    QChartView* m_fragilityChart;
    QChartView* m_integrandChart;
    BackgroundJob m_job;
    std::optional<ProjectHazard> m_hazard;
    std::vector<StudyRow> m_rows;
    std::optional<RiskOutcome> m_outcome;
};

} // namespace kinstab::ui
