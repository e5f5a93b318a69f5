// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/SweepRunner.h"

#include "core/sweep/CriticalAmplitude.h"
#include "core/sweep/ModelPoint.h"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <thread>
#include <unordered_map>

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace kinstab::ui {

// State shared by the GUI and the worker threads (cancel and counters from JobContext); outlives
// both through shared_ptr.
struct SweepRunner::Live : JobContext {
    std::mutex mutex;
    SweepResult partial; // guarded by mutex
};

namespace {

std::unordered_map<double, std::size_t> indexOf(const std::vector<double>& values) {
    std::unordered_map<double, std::size_t> m;
    for (std::size_t i = 0; i < values.size(); ++i)
        m.emplace(values[i], i);
    return m;
}

// Runs f(k) for k in [0, n) on `threads` threads, stopping early on cancel.
template <class F> void parallelFor(std::size_t n, int threads, const SweepControl& control, F f) {
    std::atomic<std::size_t> next{0};
    auto work = [&] {
        for (std::size_t k; !control.isCancelled() && (k = next.fetch_add(1)) < n;)
            f(k);
    };
    const int t = std::clamp<int>(
        threads > 0 ? threads : static_cast<int>(std::thread::hardware_concurrency()), 1,
        static_cast<int>(std::max<std::size_t>(n, 1)));
    std::vector<std::thread> pool;
    for (int i = 1; i < t; ++i)
        pool.emplace_back(work);
    work();
    for (auto& th : pool)
        th.join();
}

SweepOutput runJob(const SweepJob& job, SweepRunner::Live& live) {
    const ModelPoint model = modelPoint(job.slabCase, job.planar); // 1-DOF or planar
    const PointFunction base = model.point;
    const double scanFrom = model.scanFrom;
    // A cancelled search returns at once: criticalAmplitude then ends within one point.
    const PointFunction point = [&live, base](double a, double f) {
        if (live.control.isCancelled()) return PointResult{Outcome::Failed, 0};
        return base(a, f);
    };
    const auto ai = indexOf(job.grid.amplitudes);
    const auto fi = indexOf(job.grid.frequencies);
    const std::size_t nf = job.grid.frequencies.size();
    const PointFunction recording = [&](double a, double f) {
        const PointResult r = point(a, f);
        const std::size_t k = ai.at(a) * nf + fi.at(f);
        std::lock_guard lock(live.mutex);
        live.partial.points[k] = r;
        live.partial.done[k] = 1;
        ++live.partial.completed;
        return r;
    };
    live.control.onProgress = [&live](std::size_t, std::size_t) { ++live.done; };

    SweepOutput out;
    out.tauRef = model.tauRef;
    out.sweep = runSweep(job.grid, recording, &live.control, job.threads);
    if (job.criticalCurve && !live.control.isCancelled()) {
        out.aCrit.assign(nf, std::nullopt);
        const double top =
            *std::max_element(job.grid.amplitudes.begin(), job.grid.amplitudes.end());
        const CriticalSearch search{0.0, top, 0.01, 1e-5};
        parallelFor(nf, job.threads, live.control, [&](std::size_t j) {
            out.aCrit[j] =
                criticalAmplitude(point, job.grid.frequencies[j], scanFrom, search).amplitude;
            ++live.done;
        });
    }
    if (!job.codes.empty() && !live.control.isCancelled()) {
        try {
            out.check = designCheck(job.codes, job.slabCase, job.search, point, scanFrom);
        } catch (const std::exception& e) {
            out.checkError = e.what();
        }
        ++live.done;
    }
    out.cancelled = live.control.isCancelled();
    if (out.cancelled) {
        out.aCrit.clear();
        out.check.reset();
    }
    return out;
}

// Runs the job on its own thread a few nice levels below the GUI, so that on a busy machine
// the event loop still gets the CPU within a frame or two. Threads inherit the nice value on
// Linux, so runSweep's workers run niced too; the thread ends with the job, so no pool thread
// is left niced (an unprivileged process cannot lower its nice value again).
SweepOutput runNiced(const SweepJob& job, SweepRunner::Live& live) {
    SweepOutput out;
    std::thread worker([&] {
#ifdef __linux__
        const auto tid = static_cast<id_t>(syscall(SYS_gettid));
        setpriority(PRIO_PROCESS, tid, getpriority(PRIO_PROCESS, tid) + 5);
#endif
        out = runJob(job, live);
    });
    worker.join();
    return out;
}

} // namespace

SweepRunner::SweepRunner(QObject* parent) : QObject(parent), m_job(this, updateIntervalMs) {
    connect(&m_job, &BackgroundJob::progress, this, &SweepRunner::poll);
}

SweepRunner::~SweepRunner() = default; // m_job cancels and waits

std::size_t SweepRunner::stepCount(const SweepJob& job) {
    return job.grid.size() + (job.criticalCurve ? job.grid.frequencies.size() : 0) +
           (job.codes.empty() ? 0 : 1);
}

void SweepRunner::start(const SweepJob& job) {
    if (isRunning()) return;
    auto live = std::make_shared<Live>();
    live->total = stepCount(job);
    live->partial.grid = job.grid;
    live->partial.points.assign(job.grid.size(), PointResult{Outcome::Failed, std::nan("")});
    live->partial.done.assign(job.grid.size(), 0);
    m_live = live;
    // Inputs and the shared state are captured by value: the work never touches `this`.
    m_job.start<SweepOutput>([job, live](JobContext&) { return runNiced(job, *live); },
                             [this](SweepOutput out) { emit finished(out); }, live);
}

void SweepRunner::cancel() {
    m_job.cancel();
}

bool SweepRunner::isRunning() const {
    return m_job.isRunning();
}

SweepResult SweepRunner::snapshot() const {
    if (!m_live) return {};
    std::lock_guard lock(m_live->mutex);
    return m_live->partial;
}

void SweepRunner::poll(qint64 done, qint64 total) {
    emit progress(done, total);
    emit partialResult(snapshot());
}

} // namespace kinstab::ui
