// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Runs a sweep (and the A_crit(f) curve and the design check) off the GUI thread on a
// BackgroundJob, through core's analysis entry point (core/analysis/RunAnalysis.h). Partial results
// are polled a few times a second with its progress (never per point), and a cancel keeps
// everything already computed.

#include "core/check/DesignCheck.h"
#include "core/slab/PlanarCase.h"
#include "core/slab/Slab1DCase.h"
#include "core/sweep/Sweep.h"
#include "ui/BackgroundJob.h"

#include <QObject>

#include <memory>
#include <optional>

namespace kinstab::ui {

struct SweepJob {
    Slab1DCase slabCase;
    std::optional<PlanarCase> planar; // set: the planar model runs (slabCase gives the check's mu)
    SweepGrid grid;
    std::vector<CodeResult> codes; // the design check runs on these (none: no check)
    CriticalSearch search;         // of the design check
    bool criticalCurve = true;     // A_crit at every grid frequency
    int threads = 0;               // 0: all cores
};

struct SweepOutput {
    SweepResult sweep;
    double tauRef = 1;
    std::vector<std::optional<double>> aCrit; // per grid frequency; empty when not computed
    std::optional<DesignCheckResult> check;   // absent when cancelled, no codes, or failed
    std::string checkError;
    bool cancelled = false;
};

class SweepRunner : public QObject {
    Q_OBJECT
public:
    explicit SweepRunner(QObject* parent = nullptr);
    ~SweepRunner() override; // cancels and waits: the task must not outlive its owner

    void start(const SweepJob& job);
    void cancel();
    bool isRunning() const;
    void waitForFinished() { m_job.waitForFinished(); }
    // Everything computed so far (unfinished points have done = 0).
    SweepResult snapshot() const;

    // The units progress counts: grid points, A_crit at each frequency, the design check.
    static std::size_t stepCount(const SweepJob& job);
    static constexpr int updateIntervalMs = BackgroundJob::defaultPollMs; // surface refresh

    struct Live; // state shared with the worker threads

signals:
    // Units done of the total (grid points, A_crit frequencies, the design check).
    void progress(qint64 done, qint64 total);
    void partialResult(const kinstab::SweepResult& r);
    void finished(const kinstab::ui::SweepOutput& out);

private:
    void poll(qint64 done, qint64 total);

    std::shared_ptr<Live> m_live;
    BackgroundJob m_job;
};

} // namespace kinstab::ui
