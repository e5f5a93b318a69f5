// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Every result the main window shows, each bound to a fingerprint of the inputs that made it,
// so that no result is ever shown under inputs it was not computed with.
//
// The inputs split in two, and each result names what it depends on:
//   sweep inputs: slab, wall, envelope, scaling, model, planar settings, grid, A_crit search,
//                 excitation (sine or record) — the γc surface, A_crit(f), the picked history,
//                 the record run and the A_crit behind every verdict depend on these;
//   code inputs:  building and code inputs — only the verdicts depend on these.
// A code-only change keeps the surface and A_crit and re-judges the verdicts at once where the
// kept A_crit serves (same building frequency, or the record's critical peak, which serves every
// code); anything else that no longer matches the inputs is stale until the next run.

#include "core/check/DesignCheck.h"
#include "core/io/Project.h"
#include "core/slab/PlanarCase.h"
#include "core/slab/Slab1DCase.h"
#include "core/sweep/CriticalRecordScale.h"
#include "core/sweep/Sweep.h"
#include "ui/PlanarPointRun.h"
#include "ui/PointRun.h"
#include "ui/RecordRunner.h"
#include "ui/SurfaceData.h"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace kinstab::ui {

struct InputFingerprint {
    std::string sweep; // canonical JSON of the sweep inputs
    std::string codes; // canonical JSON of the code inputs
    bool operator==(const InputFingerprint&) const = default;
};

// The project's inputs as the two fingerprints (project name and description are neither).
InputFingerprint fingerprintOf(const Project& p);

// The γc surface of one sweep (finished, cancelled or still running) and what it was run with.
// The case is held once, as core's request holds it (core/analysis/AnalysisRequest.h): the 1-DOF
// case and, when the planar model ran, its own inputs on that case.
struct SurfaceResult {
    Slab1DCase slabCase;
    std::optional<PlanarInputs> planar; // set: the planar model ran
    SweepResult sweep;
    GammaGrid gamma;
    std::vector<std::pair<double, double>> aCrit; // (f, A_crit) of a finished sweep

    // The planar case that ran (slabCase with the planar inputs), or none.
    std::optional<PlanarCase> planarCase() const {
        if (!planar) return std::nullopt;
        return PlanarCase(slabCase, *planar);
    }
};

// Where the verdicts' A_crit came from, so they can be re-judged for new code ratios.
struct CheckSource {
    enum class Source { Sine, Record };
    Source source = Source::Sine;
    double searchLimit = 0; // A_crit search limit (g), for codes where nothing collapsed
    // Record: the critical peak of the scaled record, which serves every code.
    std::optional<RecordCriticalScale> recordCritical;
    CriticalSearch search; // of the record's verdicts
};

class ResultState {
public:
    // New or Open: no result at all.
    void clear();

    // The inputs now on the panels (none: some input is invalid, so every result is stale).
    // codes: the code results of those inputs, used to re-judge a kept A_crit. Returns true
    // when the verdict was recomputed from kept results (no run needed).
    bool setInputs(const std::optional<InputFingerprint>& now,
                   const std::vector<CodeResult>& codes);

    // The run whose results are awaited: after New/Open none is, so a run still ending from the
    // previous project is dropped instead of shown under the new one.
    enum class Run { None, Sweep, Record };
    bool awaits(Run r) const { return m_pending == r; }
    void runEnded() { m_pending = Run::None; }

    // A sweep started with the current inputs: the old surface, curve, history and check go.
    void startSweep(const Slab1DCase& c, const std::optional<PlanarInputs>& planar);
    void setSweepProgress(const SweepResult& r, const GammaGrid& g);
    void setACrit(std::vector<std::pair<double, double>> aCrit);
    // Verdicts made with the inputs the run started with.
    void setCheck(const DesignCheckResult& check, const CheckSource& basis);
    void setPicked(std::optional<PointRun> run, std::optional<PlanarPointRun> planar);
    // A record run started with the current inputs: old record run and check go.
    void startRecordRun();
    void setRecordRun(const RecordOutput& out);

    const std::optional<SurfaceResult>& surface() const { return m_surface; }
    const std::optional<PointRun>& picked() const { return m_picked; }
    const std::optional<PlanarPointRun>& pickedPlanar() const { return m_pickedPlanar; }
    const std::optional<DesignCheckResult>& check() const { return m_check; }
    const CheckSource& checkBasis() const { return m_basis; }
    const std::optional<RecordOutput>& recordRun() const { return m_record; }

    // A result that exists but was made with other inputs than the panels now show.
    bool surfaceStale() const;
    bool checkStale() const;
    bool recordStale() const;

private:
    std::optional<InputFingerprint> m_now;
    InputFingerprint m_runKey; // inputs of the run in progress or last run
    Run m_pending = Run::None;

    std::optional<SurfaceResult> m_surface;
    std::string m_surfaceKey;
    std::optional<PointRun> m_picked;
    std::optional<PlanarPointRun> m_pickedPlanar;
    std::optional<DesignCheckResult> m_check;
    CheckSource m_basis;
    InputFingerprint m_checkKey;
    std::optional<RecordOutput> m_record;
    std::string m_recordKey;
};

// The verdicts of `codes` from the A_crit a check already found: nullopt when some code's
// building frequency has no A_crit there (a new period needs a new search).
std::optional<DesignCheckResult> rejudge(const DesignCheckResult& kept, const CheckSource& basis,
                                         const std::vector<CodeResult>& codes);

} // namespace kinstab::ui
