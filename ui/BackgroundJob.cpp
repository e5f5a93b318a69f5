// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/BackgroundJob.h"

#include <QFutureWatcher>
#include <QtConcurrent/QtConcurrentRun>

#include <algorithm>
#include <exception>

namespace kinstab::ui {

BackgroundJob::BackgroundJob(QObject* parent, int pollMs) : QObject(parent) {
    m_timer.setInterval(pollMs);
    connect(&m_timer, &QTimer::timeout, this, &BackgroundJob::poll);
}

BackgroundJob::~BackgroundJob() {
    ++m_generation; // nothing delivers from here on (queued finishes die with this object)
    for (Running& r : m_running)
        r.context->cancel();
    for (Running& r : m_running)
        r.future.waitForFinished();
}

void BackgroundJob::launch(std::function<void(JobContext&)> work, std::function<void()> deliver,
                           std::shared_ptr<JobContext> context) {
    cancel(); // the job still running, if any, is superseded
    std::erase_if(m_running, [](const Running& r) { return r.future.isFinished(); });
    const quint64 id = ++m_generation;
    m_context = context;
    auto error = std::make_shared<QString>();
    // The worker captures only shared state and the work: it never touches `this`.
    QFuture<void> future = QtConcurrent::run([work, context, error] {
        try {
            work(*context);
        } catch (const std::exception& e) {
            *error = QString::fromUtf8(e.what());
        } catch (...) {
            *error = QStringLiteral("unknown error");
        }
    });
    m_running.push_back({future, context});
    auto* watcher = new QFutureWatcher<void>(this);
    connect(watcher, &QFutureWatcherBase::finished, this, [this, watcher, id, deliver, error] {
        watcher->deleteLater();
        if (id != m_generation) return; // superseded: its result is dropped
        m_timer.stop();
        poll();
        if (error->isEmpty())
            deliver();
        else
            emit failed(*error);
        emit ended();
    });
    watcher->setFuture(future);
    m_timer.start();
}

void BackgroundJob::cancel() {
    if (m_context) m_context->cancel();
}

void BackgroundJob::discard() {
    cancel();
    ++m_generation; // its watcher's delivery sees another number and drops the result
    m_timer.stop();
}

bool BackgroundJob::isRunning() const {
    return !m_running.empty() && !m_running.back().future.isFinished();
}

void BackgroundJob::waitForFinished() {
    if (!m_running.empty()) m_running.back().future.waitForFinished();
}

void BackgroundJob::poll() {
    if (!m_context) return;
    const auto [done, total] = m_context->counts();
    emit progress(static_cast<qint64>(done), static_cast<qint64>(total));
}

} // namespace kinstab::ui
