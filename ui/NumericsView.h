// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Numerics view (docs/theory.md §6.6): the work-precision study of
// core/precision/WorkPrecision.h as a log-log plot of error against run time, one curve per case
// and solver, and its table. The study runs off the GUI thread; Cancel takes effect after the row
// in progress.

#include "core/precision/WorkPrecision.h"
#include "ui/BackgroundJob.h"

#include <QWidget>

class QChartView;
class QCheckBox;
class QHBoxLayout;
class QPlainTextEdit;
class QProgressBar;
class QPushButton;
class QSplitter;

namespace kinstab::ui {

class NumericsView : public QWidget {
    Q_OBJECT
public:
    explicit NumericsView(QWidget* parent = nullptr);
    ~NumericsView() override;

    void startStudy();
    void cancelStudy();
    bool isRunning() const;
    // Shows a finished study (also used by tests with a study computed elsewhere).
    void showStudy(const WorkPrecisionStudy& study);
    int curveCount() const;

signals:
    void studyShown();

private:
    QHBoxLayout* buildBar();
    QSplitter* buildChartAndTable();
    void onProgress(qint64 done, qint64 total);
    void onEnded();

    QPushButton* m_run = nullptr;
    QPushButton* m_cancel = nullptr;
    QCheckBox* m_regularized = nullptr;
    QProgressBar* m_progress = nullptr;
    QChartView* m_chart = nullptr;
    QPlainTextEdit* m_table = nullptr;
    BackgroundJob m_job;
    int m_curves = 0;
};

} // namespace kinstab::ui
