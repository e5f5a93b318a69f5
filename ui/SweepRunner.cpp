// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/SweepRunner.h"

#include "core/analysis/RunAnalysis.h"
#include "core/assessment/ProjectRequest.h"

#include <algorithm>
#include <cmath>
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

CriticalSearch surfaceCurveSearch(double topAmplitude) {
    CriticalSearch s;
    s.from = 0.0;
    s.to = topAmplitude;
    s.scanStep = kScanStepInput.fallback;
    s.tolerance = kSurfaceCurveTolerance;
    return s;
}

AnalysisRequest surfaceRunRequest(const Project& p) {
    AnalysisParts parts;
    parts.surface = true;
    parts.criticalCurve = true;
    AnalysisRequest q = analysisRequest(p, parts);
    q.parts.designCheck = !q.codes.empty();
    const auto& amplitudes = q.grid.amplitudes;
    const double top =
        amplitudes.empty() ? 0.0 : *std::max_element(amplitudes.begin(), amplitudes.end());
    q.criticalSearch = surfaceCurveSearch(top);
    return q;
}

namespace {

AnalysisResult runJob(const AnalysisRequest& request, SweepRunner::Live& live) {
    // Each finished point goes into the snapshot the GUI polls, at its grid index.
    live.analysis.onPoint = [&live](std::size_t k, const PointResult& r) {
        std::lock_guard lock(live.mutex);
        live.partial.points[k] = r;
        live.partial.done[k] = 1;
        ++live.partial.completed;
    };
    return runAnalysis(request, live.analysis);
}

// Runs the job on its own thread a few nice levels below the GUI, so that on a busy machine
// the event loop still gets the CPU within a frame or two. Threads inherit the nice value on
// Linux, so runSweep's workers run niced too; the thread ends with the job, so no pool thread
// is left niced (an unprivileged process cannot lower its nice value again).
AnalysisResult runNiced(const AnalysisRequest& request, SweepRunner::Live& live) {
    AnalysisResult out;
    std::thread worker([&] {
#ifdef __linux__
        const auto tid = static_cast<id_t>(syscall(SYS_gettid));
        setpriority(PRIO_PROCESS, tid, getpriority(PRIO_PROCESS, tid) + 5);
#endif
        out = runJob(request, live);
    });
    worker.join();
    return out;
}

} // namespace

SweepRunner::SweepRunner(QObject* parent) : QObject(parent), m_job(this, updateIntervalMs) {
    connect(&m_job, &BackgroundJob::progress, this, &SweepRunner::poll);
}

SweepRunner::~SweepRunner() = default; // m_job cancels and waits

void SweepRunner::start(const AnalysisRequest& request) {
    if (isRunning()) return;
    auto live = std::make_shared<Live>();
    live->partial.grid = request.grid;
    live->partial.points.assign(request.grid.size(), PointResult{Outcome::Failed, std::nan("")});
    live->partial.done.assign(request.grid.size(), 0);
    m_live = live;
    // Inputs and the shared state are captured by value: the work never touches `this`.
    m_job.start<AnalysisResult>([request, live](JobContext&) { return runNiced(request, *live); },
                                [this](AnalysisResult out) { emit finished(out); }, live);
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
