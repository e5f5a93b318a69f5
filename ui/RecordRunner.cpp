// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/RecordRunner.h"

#include "ui/RecordPointRun.h"

#include <QPromise>
#include <QtConcurrent>

#include <atomic>

namespace kinstab::ui {

struct RecordRunner::Live {
    SweepControl control;
    std::atomic<std::size_t> done{0}, total{1};
};

RecordOutput runRecordJob(const RecordAnalysisInput& input, SweepControl* control) {
    RecordOutput out;
    try {
        RecordAnalysisInput in = input;
        in.events = true; // the history chart needs them
        out.analysis = analyseRecord(in, control);
        out.cancelled = out.analysis->cancelled;
        out.history = recordPointRun(in.slab, *out.analysis);
    } catch (const RecordError& e) {
        out.error = "excitation.record.file = '" + input.record.file + "': " + e.what();
    } catch (const std::exception& e) {
        out.error = e.what();
    }
    return out;
}

RecordRunner::RecordRunner(QObject* parent) : QObject(parent) {
    m_timer.setInterval(250);
    connect(&m_timer, &QTimer::timeout, this, &RecordRunner::poll);
    connect(&m_watcher, &QFutureWatcher<RecordOutput>::finished, this, &RecordRunner::onFinished);
}

RecordRunner::~RecordRunner() {
    cancel();
    m_watcher.waitForFinished();
}

void RecordRunner::start(const RecordAnalysisInput& input) {
    if (isRunning()) return;
    auto live = std::make_shared<Live>();
    live->control.onProgress = [raw = live.get()](std::size_t done, std::size_t total) {
        raw->done = done;
        raw->total = std::max<std::size_t>(total, 1);
    };
    m_live = live;
    // Inputs and the shared state by value: the task never touches `this`.
    m_watcher.setFuture(QtConcurrent::run([input, live](QPromise<RecordOutput>& promise) {
        promise.addResult(runRecordJob(input, &live->control));
    }));
    m_timer.start();
}

void RecordRunner::cancel() {
    if (m_live) m_live->control.cancel();
}

bool RecordRunner::isRunning() const {
    return m_watcher.isRunning();
}

void RecordRunner::poll() {
    if (m_live)
        emit progress(static_cast<qint64>(m_live->done.load()),
                      static_cast<qint64>(m_live->total.load()));
}

void RecordRunner::onFinished() {
    m_timer.stop();
    if (m_watcher.future().resultCount() == 0) return;
    poll();
    emit finished(m_watcher.result());
}

} // namespace kinstab::ui
