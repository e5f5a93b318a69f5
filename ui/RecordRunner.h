// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Runs a record analysis off the GUI thread (core/check/RecordAnalysis.h: the single run, the
// critical scale and the verdicts) on a BackgroundJob, like SweepRunner: progress polled a few
// times a second, cancel within one slab run.

#include "core/check/RecordAnalysis.h"
#include "ui/BackgroundJob.h"
#include "ui/PointRun.h"

#include <QObject>

#include <optional>

namespace kinstab::ui {

struct RecordOutput {
    std::optional<RecordAnalysis> analysis; // none when the input failed
    std::optional<PointRun> history;        // the single run, sampled for HistoryChart
    std::string error;                      // why it failed (names the field or file)
    bool cancelled = false;
};

class RecordRunner : public QObject {
    Q_OBJECT
public:
    explicit RecordRunner(QObject* parent = nullptr);
    ~RecordRunner() override; // m_job cancels and waits

    void start(const RecordAnalysisInput& input);
    void cancel();
    bool isRunning() const;
    void waitForFinished() { m_job.waitForFinished(); }

signals:
    void progress(qint64 done, qint64 total);
    void finished(const kinstab::ui::RecordOutput& out);

private:
    BackgroundJob m_job;
};

// The work itself, synchronous (the runner calls it on its worker; tests call it directly).
RecordOutput runRecordJob(const RecordAnalysisInput& input, SweepControl* control = nullptr);

} // namespace kinstab::ui
