// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Runs a sweep (and the A_crit(f) curve and the design check) off the GUI thread on a
// BackgroundJob, through core's analysis entry point (core/analysis/RunAnalysis.h). Partial results
// are polled a few times a second with its progress (never per point), and a cancel keeps
// everything already computed.

#include "core/analysis/AnalysisRequest.h"
#include "core/analysis/AnalysisResult.h"
#include "core/io/Project.h"
#include "core/sweep/Sweep.h"
#include "ui/BackgroundJob.h"

#include <QObject>

#include <memory>

namespace kinstab::ui {

// The GUI's Run of a project (core/assessment/ProjectRequest.h): the surface, A_crit at every
// grid frequency searched up to the grid's top amplitude (surfaceCurveSearch), and the design
// check when there are codes. Throws InputError as analysisRequest does.
AnalysisRequest surfaceRunRequest(const Project& p);

// The A_crit(f) curve drawn over a surface: scanned from each model's no-slip amplitude (from = 0
// defers to it) up to the grid's top amplitude in the default scan step, bisected to
// kSurfaceCurveTolerance.
CriticalSearch surfaceCurveSearch(double topAmplitude);
// g: the curve spans amplitudes of order 0.1 to 10 g, where that is far below a pixel (the
// default search's 1e-6 g is for the design check's printed digits, not a drawn curve).
inline constexpr double kSurfaceCurveTolerance = 1e-5;

class SweepRunner : public QObject {
    Q_OBJECT
public:
    explicit SweepRunner(QObject* parent = nullptr);
    ~SweepRunner() override; // cancels and waits: the task must not outlive its owner

    void start(const AnalysisRequest& request);
    void cancel();
    bool isRunning() const;
    void waitForFinished() { m_job.waitForFinished(); }
    // Everything computed so far (unfinished points have done = 0).
    SweepResult snapshot() const;

    static constexpr int updateIntervalMs = BackgroundJob::defaultPollMs; // surface refresh

    struct Live; // state shared with the worker threads

signals:
    // Units done of the total (grid points, A_crit frequencies, the design check).
    void progress(qint64 done, qint64 total);
    void partialResult(const kinstab::SweepResult& r);
    // The result of core's analysis: the surface always, the curve and check as asked.
    void finished(const kinstab::AnalysisResult& out);

private:
    void poll(qint64 done, qint64 total);

    std::shared_ptr<Live> m_live;
    BackgroundJob m_job;
};

} // namespace kinstab::ui
