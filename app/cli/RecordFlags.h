// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Flags that name an accelerogram file and how to read it (docs/theory.md §7; docs/user-guide.md
// "The command line"), shared by `simulate --record`, `record --file` and the planar model's
// `--vertical`:
//   --record-format auto|at2|cosmos|csmip|values|time-accel   --record-dt S
//   --record-unit g|m/s2|cm/s2|ft/s2|in/s2   --record-channel N|NAME (CSMIP V2)
//   --floor-period T [--damping Z]: pass the record through the floor filter first.

#include "app/cli/Args.h"
#include "core/excitation/FloorFilter.h"
#include "core/excitation/RecordExcitation.h"
#include "core/io/RecordJson.h" // the record and floor filter as the commands write them
#include "core/records/RecordReader.h"

#include <nlohmann/json.hpp>
#include <optional>
#include <set>

namespace kinstab::cli {

std::set<std::string> recordReadFlagNames();
RecordReadOptions recordReadOptionsFromFlags(const Args& args);
// Reads the file named by --<fileFlag>; a broken file is a UsageError "--record FILE: FILE:LINE:
// ...".
Accelerogram readRecordFromFlag(const Args& args, const std::string& fileFlag);
// --floor-period / --damping; none when --floor-period is absent (--damping alone is an error).
std::optional<FloorFilterParams> floorFilterFromFlags(const Args& args);

// The record excitation of simulate --record: the file, its read flags, --floor-period/--damping
// and the scaling (--amplitude PEAK_G or --scale-factor F, exclusive; neither: as recorded).
// Checks the flags only; the file is read later.
RecordExcitation recordExcitationFromFlags(const Args& args, const std::string& fileFlag);

} // namespace kinstab::cli
