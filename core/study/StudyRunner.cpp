// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/StudyRunner.h"

#include "core/building/FloorMotions.h"
#include "core/excitation/FloorFilter.h"
#include "core/study/CaseCritical.h"
#include "core/sweep/ParallelFor.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace kinstab {

namespace {

double maxAbs(const std::vector<double>& v) {
    double m = 0.0;
    for (double x : v)
        m = std::max(m, std::abs(x));
    return m;
}

// The unscaled ground record's intensity measure (g).
double recordIntensity(const IntensityMeasure& im, const Accelerogram& ground) {
    if (im.kind == IntensityMeasure::Kind::Pga) return maxAbs(ground.samples);
    return maxAbs(floorAcceleration(ground.samples, ground.dt, im.period, im.damping));
}

// Every level's absolute acceleration in the study's building under the ground record.
std::vector<Accelerogram> levelMotions(const StudySpec& s, const Accelerogram& ground) {
    return floorMotions(s.building->model, ground, {s.building->settings.damping, std::nullopt});
}

// The motion under the slab: the ground record, through the floor filter, or the case's level.
// A level's motion is the one built when the record was read, negated for the inverted polarity:
// the building is linear and rounding is symmetric in sign, so that is bit for bit the motion
// under the inverted ground.
Accelerogram caseMotion(const StudySpec& s, const StudyCase& c, const Accelerogram& ground) {
    if (c.level > 0 && c.record->levelMotions) {
        Accelerogram m = (*c.record->levelMotions)[static_cast<std::size_t>(c.level - 1)];
        if (c.inverted)
            for (double& a : m.samples)
                a = -a;
        return m;
    }
    if (c.level > 0) return levelMotions(s, ground)[static_cast<std::size_t>(c.level - 1)];
    if (c.floor) return floorMotion(ground, {c.floor->period, c.floor->damping, std::nullopt});
    return ground;
}

// The record as given in the suite (the file times its scale) against its critical intensity.
void addAsGiven(const StudyRecord& record, StudyRow& row) {
    row.scale = record.scale;
    row.imAsGiven = record.scale * row.recordIntensity;
    if (!row.criticalIntensity) return;
    row.collapsesAsGiven = *row.criticalIntensity <= row.imAsGiven;
    row.margin = *row.criticalIntensity / row.imAsGiven;
}

// The case's critical peak of the driving motion: the block's overturning, or the slab's
// collapse.
CaseCritical criticalOf(const StudySpec& s, const StudyCase& c, const Accelerogram& motion,
                        bool& runLimitReached) {
    if (s.block) {
        const BlockCaseCritical b = blockCaseCritical(*s.block, motion, s.search);
        runLimitReached = b.runLimitReached;
        return {b.peak, b.unitPeak, b.runs, {}};
    }
    Slab1DCase slab;
    slab.tstar = c.tstar;
    slab.slab.mu = c.mu;
    slab.slab.limit = s.limit;
    return caseCritical(slab, motion, c.motion, s.search);
}

} // namespace

Accelerogram caseGround(const Accelerogram& record, bool inverted) {
    Accelerogram g = record;
    if (inverted)
        for (double& a : g.samples)
            a = -a;
    return g;
}

StudyRow runStudyCase(const StudySpec& s, const StudyCase& c) {
    if (!c.record->ground) throw std::logic_error("runStudyCase: the records were not read");
    const Accelerogram ground = caseGround(*c.record->ground, c.inverted);
    const Accelerogram motion = caseMotion(s, c, ground);
    bool runLimitReached = false;
    const CaseCritical crit = criticalOf(s, c, motion, runLimitReached);
    // The record is linear in its scale, and so are the floor filter and the building: the
    // intensity at a scale is the unscaled intensity times (scaled peak / unscaled peak) of the
    // driving motion (of its surrogate's envelope, for the fitted sine).
    StudyRow row = studyRowInputs(s, c);
    row.recordIntensity = recordIntensity(s.intensity, ground);
    const double perPeak = row.recordIntensity / crit.unitPeak;
    if (crit.peak) {
        row.criticalPeak = *crit.peak;
        row.criticalIntensity = *crit.peak * perPeak;
    }
    row.limitIntensity = s.search.to * perPeak;
    row.runs = crit.runs;
    row.noFit = crit.noFit;
    row.runLimitReached = runLimitReached;
    if (s.asGiven) addAsGiven(*c.record, row);
    return row;
}

namespace {

// Runs the cases of indices on core's one thread pool (core/sweep/ParallelFor.h), each row into
// its slot; the first failing case's exception is rethrown, as a plain loop would meet it.
void runBlock(const StudySpec& s, const std::vector<std::size_t>& indices, unsigned threads,
              const SweepControl* control, std::vector<StudyRow>& rows) {
    parallelFor(indices.size(), static_cast<int>(threads), control,
                [&](std::size_t i) { rows[i] = runStudyCase(s, studyCase(s, indices[i])); });
}

} // namespace

std::size_t shardCaseCount(const StudySpec& s, const Shard& shard) {
    const std::size_t total = studyCaseCount(s);
    return total / shard.n + (total % shard.n >= shard.k ? 1 : 0);
}

std::size_t runStudy(const StudySpec& s, const StudyRunOptions& o, const StudyRowSink& sink) {
    const std::size_t total = studyCaseCount(s);
    const std::size_t mine = shardCaseCount(s, o.shard);
    const unsigned threads = std::max(1u, o.threads);
    const std::size_t blockSize = 16 * static_cast<std::size_t>(threads);
    std::size_t written = 0;
    std::vector<std::size_t> indices;
    std::vector<StudyRow> rows;
    if (o.done >= mine) return 0;
    // Every loop is bounded by the shard's case count; a block is at most blockSize cases.
    for (std::size_t start = o.shard.k - 1 + o.done * o.shard.n; start < total;) {
        indices.clear();
        for (; start < total && indices.size() < blockSize; start += o.shard.n)
            indices.push_back(start);
        rows.assign(indices.size(), StudyRow());
        runBlock(s, indices, threads, o.control, rows);
        if (o.control && o.control->isCancelled()) return written;
        sink(rows);
        written += indices.size();
        if (o.control && o.control->onProgress) o.control->onProgress(o.done + written, mine);
    }
    return written;
}

std::vector<StudyRow> runStudyRows(const StudySpec& s, const StudyRunOptions& options) {
    std::vector<StudyRow> rows;
    runStudy(s, options, [&rows](const std::vector<StudyRow>& block) {
        rows.insert(rows.end(), block.begin(), block.end());
    });
    return rows;
}

} // namespace kinstab
