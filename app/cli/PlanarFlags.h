// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The planar model's flags (docs/user-guide.md "The command line"): --ay-ratio R (0.9), --fy F (Hz,
// required), --theta X (20),
// --vertical FILE (none: gravity only), --normalization product|envelope (product).

#include "app/cli/Args.h"
#include "core/io/CaseJson.h"
#include "core/slab/PlanarCase.h"

#include <nlohmann/json.hpp>
#include <string>

namespace kinstab::cli {

bool isPlanar(const Args& args); // --model planar
// Reads and validates the planar case; throws UsageError naming the bad flag.
// recordDriven: the horizontal motion comes from --record (PlanarRecord.cpp), so --fy is not
// required and --record/--floor-period/--damping are the caller's.
PlanarCase planarCaseFromFlags(const Args& args, bool recordDriven = false);

// The planar branch of simulate, after the shared flags are read.
int runSimulatePlanar(const Args& args, double amplitude, double frequency, double historyStep);
// Shared by the sine- and record-driven planar simulate: the path CSV (the result's JSON is
// core/io/PlanarResultJson.h's).
std::string planarHistoryCsv(const SlabModel2D& m, const std::vector<PlanarSample>& path);
// What --events and --history ask a run to keep.
struct PlanarCliLogs {
    explicit PlanarCliLogs(const Args& args);
    PlanarEventLog events;
    PlanarPathLog path;
    PlanarRecorderPair recorder;
};

// simulate --model planar --record FILE [--record-y FILE] (PlanarRecord.cpp).
int runSimulatePlanarRecord(const Args& args);

} // namespace kinstab::cli
