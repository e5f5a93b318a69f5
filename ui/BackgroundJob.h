// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one way the GUI runs long work off its thread (sweeps, record runs, the numerics study,
// the report's analyses, the teaching map). The work gets a JobContext: core's SweepControl to
// see a cancel, and done/total counters it advances. The GUI reads those counters from a timer
// a few times a second, never a signal per point. The result comes back exactly once, on the
// GUI thread. A job superseded by a newer start() is cancelled and its late result dropped. The
// destructor cancels and waits, so no worker outlives the object that started it.

#include "core/analysis/AnalysisControl.h"
#include "core/sweep/SweepControl.h"

#include <QFuture>
#include <QObject>
#include <QTimer>

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace kinstab::ui {

// Shared by the worker and the GUI; outlives both through shared_ptr.
struct JobContext {
    virtual ~JobContext() = default;
    SweepControl control;              // cancel flag (and core's progress hooks)
    std::atomic<std::size_t> done{0};  // units of work finished
    std::atomic<std::size_t> total{0}; // units of work in all (0: not known yet)
    bool isCancelled() const { return control.isCancelled(); }
    virtual void cancel() { control.cancel(); }
    // (done, total) as the GUI shows them.
    virtual std::pair<std::size_t, std::size_t> counts() const {
        return {done.load(), total.load()};
    }
};

// A job that runs core's analysis entry point (core/analysis/RunAnalysis.h): its
// AnalysisControl carries the cancel and counts the steps.
struct AnalysisJobContext : JobContext {
    AnalysisControl analysis;
    void cancel() override {
        JobContext::cancel();
        analysis.cancel();
    }
    std::pair<std::size_t, std::size_t> counts() const override {
        return {analysis.done(), analysis.total()};
    }
};

class BackgroundJob : public QObject {
    Q_OBJECT
public:
    static constexpr int defaultPollMs = 250;

    explicit BackgroundJob(QObject* parent = nullptr, int pollMs = defaultPollMs);
    ~BackgroundJob() override; // cancels every job still running and waits for it

    // Runs work(context) on a pool thread and later deliver(result) on the GUI thread, unless a
    // newer start() superseded it or this object went first. A running job is superseded. The
    // work owns its exceptions: one that escapes is reported by failed() instead of a result.
    // context: the shared state to hand the work (a subclass carrying more, or a fresh one).
    template <class R>
    void start(std::function<R(JobContext&)> work, std::function<void(R)> deliver,
               std::shared_ptr<JobContext> context = std::make_shared<JobContext>()) {
        auto slot = std::make_shared<std::optional<R>>();
        launch([work, slot](JobContext& c) { slot->emplace(work(c)); },
               [slot, deliver] {
                   if (*slot) deliver(std::move(**slot));
               },
               std::move(context));
    }

    void cancel(); // asks the current job to stop; it still delivers what it has
    // Cancels the current job and drops its result: nothing is delivered and ended() is not
    // emitted (what it was computing is gone, e.g. a view cleared).
    void discard();
    bool isRunning() const;
    // Blocks until the current job's work has returned; its delivery follows from the event loop.
    void waitForFinished();
    // The current job's shared state (null before the first start).
    const std::shared_ptr<JobContext>& context() const { return m_context; }

signals:
    // The current job's counters: polled while it runs, and once more just before delivery.
    void progress(qint64 done, qint64 total);
    // The current job's work threw instead of returning a result.
    void failed(const QString& message);
    // After the current job's delivery (or failure): the job is over.
    void ended();

private:
    struct Running {
        QFuture<void> future;
        std::shared_ptr<JobContext> context;
    };
    void launch(std::function<void(JobContext&)> work, std::function<void()> deliver,
                std::shared_ptr<JobContext> context);
    void poll();

    std::shared_ptr<JobContext> m_context;
    std::vector<Running> m_running; // every worker not yet joined, the current one last
    quint64 m_generation = 0;       // the current job's number; older deliveries are dropped
    QTimer m_timer;
};

} // namespace kinstab::ui
