// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/StudyRunner.h"

#include "core/excitation/FloorFilter.h"
#include "core/excitation/RecordExcitation.h"
#include "core/sweep/CriticalRecordScale.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <exception>
#include <thread>
#include <vector>

namespace kinstab {

namespace {

RecordExcitation excitationOf(const StudyRecord& r, const std::optional<FloorFilterChoice>& f) {
    RecordExcitation e;
    e.file = r.file;
    if (f) e.floor = FloorFilterParams{f->period, f->damping, std::nullopt};
    return e;
}

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

} // namespace

void checkStudyRecords(const StudySpec& s) {
    for (const StudyRecord& r : s.records) {
        try {
            for (const auto& f : s.floors) {
                const RecordExcitation e = excitationOf(r, f);
                const Accelerogram ground = readGroundRecord(e);
                if (!(maxAbs(drivingMotion(e, ground).samples) > 0.0))
                    throw RecordError(r.file, 0, "the motion is zero throughout");
            }
        } catch (const RecordError& e) {
            throw StudyError("records: " + std::string(e.what()));
        }
    }
}

StudyRow runStudyCase(const StudySpec& s, const StudyCase& c) {
    const RecordExcitation e = excitationOf(*c.record, c.floor);
    const Accelerogram ground = readGroundRecord(e);
    const Accelerogram motion = drivingMotion(e, ground);
    Slab1DCase slab;
    slab.tstar = c.tstar;
    slab.slab.mu = c.mu;
    slab.slab.limit = s.limit;
    const RecordCriticalScale crit = criticalRecordScale(slab, motion, s.search);
    // The record is linear in its scale, and so is the floor filter: the intensity at a scale
    // is the unscaled intensity times (scaled peak / unscaled peak) of the driving motion.
    const double im = recordIntensity(s.intensity, ground);
    const double perPeak = im / crit.motionPeak;
    StudyRow row;
    row.index = c.index;
    row.cases = studyCaseCount(s);
    row.set = c.set;
    row.record = c.record->label;
    row.mu = c.mu;
    row.tstar = c.tstar;
    row.limit = s.limit;
    if (c.floor) {
        row.floorPeriod = c.floor->period;
        row.floorDamping = c.floor->damping;
    }
    row.measure = intensityName(s.intensity);
    row.recordIntensity = im;
    if (crit.peak) {
        row.criticalPeak = *crit.peak;
        row.criticalIntensity = *crit.peak * perPeak;
    }
    row.limitIntensity = s.search.to * perPeak;
    row.runs = crit.runs;
    return row;
}

namespace {

// Runs the cases of indices on `threads` workers, each row into its slot.
void runBlock(const StudySpec& s, const std::vector<std::size_t>& indices, unsigned threads,
              SweepControl* control, std::vector<std::string>& lines) {
    std::atomic<std::size_t> next{0};
    std::exception_ptr failure;
    std::atomic<bool> failed{false};
    auto work = [&] {
        for (std::size_t i = next++; i < indices.size(); i = next++) {
            if (failed || (control && control->isCancelled())) return;
            try {
                lines[i] = studyRowLine(runStudyCase(s, studyCase(s, indices[i]))) + "\n";
            } catch (...) {
                if (!failed.exchange(true)) failure = std::current_exception();
                return;
            }
        }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t)
        pool.emplace_back(work);
    work();
    for (std::thread& t : pool)
        t.join();
    if (failure) std::rethrow_exception(failure);
}

} // namespace

std::size_t runStudy(const StudySpec& s, const StudyRunOptions& o,
                     const std::function<void(const std::string&)>& sink) {
    const std::size_t total = studyCaseCount(s);
    const std::size_t mine = total / o.shard.n + (total % o.shard.n >= o.shard.k ? 1 : 0);
    const unsigned threads = std::max(1u, o.threads);
    const std::size_t blockSize = 16 * static_cast<std::size_t>(threads);
    std::size_t written = 0;
    std::vector<std::size_t> indices;
    std::vector<std::string> lines;
    // Every loop is bounded by the shard's case count; a block is at most blockSize cases.
    for (std::size_t start = o.shard.k - 1; start < total;) {
        indices.clear();
        for (; start < total && indices.size() < blockSize; start += o.shard.n)
            indices.push_back(start);
        lines.assign(indices.size(), std::string());
        runBlock(s, indices, threads, o.control, lines);
        if (o.control && o.control->isCancelled()) return written;
        std::string text;
        for (const std::string& l : lines)
            text += l;
        sink(text);
        written += indices.size();
        if (o.control && o.control->onProgress) o.control->onProgress(written, mine);
    }
    return written;
}

} // namespace kinstab
