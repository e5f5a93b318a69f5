// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// `kinstab-cli bench`'s JSON (docs/user-guide.md "The command line"): each timed variant's
// TimingStats, the grid and threads first, the case timed and the ratios between variants.

#include "core/check/RecordBenchmark.h"
#include "core/numerics/Timing.h"
#include "core/rocking/RockingBenchmark.h"
#include "core/slab/PlanarCase.h"
#include "core/slab/Slab1DCase.h"
#include "core/study/StudyBenchmark.h"
#include "core/sweep/SurfaceBenchmark.h"

#include <nlohmann/json.hpp>

#include <string>

namespace kinstab {

// min_s, median_s, median_cpu_s, runs.
nlohmann::json timingJson(const TimingStats& t);

// The exact surface against the paper's RK4 on grid: envelope, mu, the timings, their ratios,
// the points that collapsed or disagree, the CPU per point and the evaluations per event.
nlohmann::json surfaceBenchmarkJson(const SurfaceBenchmark& b, const Slab1DCase& c,
                                    const SweepGrid& grid);
// The planar surface against the 1-DOF one: the planar case's keys, the timings and ratios, and
// the planar points' outcomes and work.
nlohmann::json planarBenchmarkJson(const PlanarSurfaceBenchmark& b, const PlanarCase& c,
                                   const SweepGrid& grid);
// The exact surface with and without clearing the vector state.
nlohmann::json vectorStateBenchmarkJson(const VectorStateBenchmark& b, const SweepGrid& grid);
// The record path: a record run against a sine run at (amplitude, frequency), the fit's share,
// the record's critical search against the sine's.
nlohmann::json recordBenchmarkJson(const RecordBenchmark& b, const Slab1DCase& c,
                                   const std::string& record, double amplitude, double frequency);
// One pulse run, and the overturning map linearised and exact.
nlohmann::json rockingBenchmarkJson(const RockingBenchmark& b);
// A study's cases on one thread and on b.threads.
nlohmann::json studyBenchmarkJson(const StudyBenchmark& b, const std::string& study);

} // namespace kinstab
