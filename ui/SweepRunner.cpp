// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/SweepRunner.h"

#include "core/analysis/RunAnalysis.h"

#include <algorithm>
#include <exception>
#include <mutex>
#include <thread>

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace kinstab::ui {

// State shared by the GUI and the worker threads (cancel and counters from the analysis); outlives
// both through shared_ptr.
struct SweepRunner::Live : AnalysisJobContext {
    std::mutex mutex;
    SweepResult partial; // guarded by mutex
};

namespace {

// The A_crit(f) curve drawn over a surface: scanned from each model's no-slip amplitude (from = 0
// defers to it) up to the grid's top amplitude in the default scan step, bisected to 1e-5 g: the
// curve spans amplitudes of order 0.1 to 10 g, where that is far below a pixel (the default
// search's 1e-6 g is for the design check's printed digits, not a drawn curve).
constexpr double kSurfaceCurveTolerance = 1e-5;
CriticalSearch surfaceCriticalSearch(double topAmplitude) {
    CriticalSearch s;
    s.from = 0.0;
    s.to = topAmplitude;
    s.scanStep = kScanStepInput.fallback;
    s.tolerance = kSurfaceCurveTolerance;
    return s;
}

// The job as core's analysis request: the surface, A_crit at every grid frequency (searched up
// to the grid's top amplitude), and the design check when there are codes.
AnalysisRequest analysisRequest(const SweepJob& job) {
    AnalysisRequest q;
    q.slab = job.slabCase;
    q.planar = job.planar;
    q.grid = job.grid;
    q.criticalFrequencies = job.grid.frequencies;
    const auto& amplitudes = job.grid.amplitudes;
    const double top =
        amplitudes.empty() ? 0.0 : *std::max_element(amplitudes.begin(), amplitudes.end());
    q.criticalSearch = surfaceCriticalSearch(top);
    q.codes = job.codes;
    q.checkSearch = job.search;
    q.parts.surface = true;
    q.parts.criticalCurve = job.criticalCurve;
    q.parts.designCheck = !job.codes.empty();
    q.threads = job.threads;
    return q;
}

std::string errorText(const std::exception_ptr& e) {
    try {
        std::rethrow_exception(e);
    } catch (const std::exception& x) {
        return x.what();
    } catch (...) {
        return "unknown error";
    }
}

SweepOutput runJob(const SweepJob& job, SweepRunner::Live& live) {
    // Each finished point goes into the snapshot the GUI polls, at its grid index.
    live.analysis.onPoint = [&live](std::size_t k, const PointResult& r) {
        std::lock_guard lock(live.mutex);
        live.partial.points[k] = r;
        live.partial.done[k] = 1;
        ++live.partial.completed;
    };
    const AnalysisResult r = runAnalysis(analysisRequest(job), live.analysis);
    SweepOutput out;
    out.tauRef = r.tauRef;
    out.sweep = *r.surface;
    if (r.critical) out.aCrit = r.critical->amplitude;
    out.check = r.check;
    if (r.checkError) out.checkError = errorText(r.checkError);
    out.cancelled = r.cancelled;
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
    return analysisSteps(analysisRequest(job));
}

void SweepRunner::start(const SweepJob& job) {
    if (isRunning()) return;
    auto live = std::make_shared<Live>();
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
