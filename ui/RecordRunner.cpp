// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/RecordRunner.h"

#include "ui/RecordPointRun.h"

#include <algorithm>

namespace kinstab::ui {

RecordOutput runRecordJob(const RecordAnalysisInput& input, SweepControl* control) {
    RecordOutput out;
    try {
        SlabEventLog events; // the history chart needs them
        out.analysis = analyseRecord(input, control, &events);
        out.cancelled = out.analysis->cancelled;
        out.history = recordPointRun(input.slab, *out.analysis, events.events);
    } catch (const RecordError& e) {
        out.error = "excitation.record.file = '" + input.record.file + "': " + e.what();
    } catch (const std::exception& e) {
        out.error = e.what();
    }
    return out;
}

RecordRunner::RecordRunner(QObject* parent) : QObject(parent), m_job(this) {
    connect(&m_job, &BackgroundJob::progress, this, &RecordRunner::progress);
}

RecordRunner::~RecordRunner() = default;

void RecordRunner::start(const RecordAnalysisInput& input) {
    if (isRunning()) return;
    // The input by value: the work never touches `this`.
    m_job.start<RecordOutput>(
        [input](JobContext& job) {
            job.total = 1;
            job.control.onProgress = [&job](std::size_t done, std::size_t total) {
                job.done = done;
                job.total = std::max<std::size_t>(total, 1);
            };
            return runRecordJob(input, &job.control);
        },
        [this](RecordOutput out) { emit finished(out); });
}

void RecordRunner::cancel() {
    m_job.cancel();
}

bool RecordRunner::isRunning() const {
    return m_job.isRunning();
}

} // namespace kinstab::ui
