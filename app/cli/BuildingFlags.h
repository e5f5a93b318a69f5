// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The building and code flags of `kinstab-cli codes` (docs/user-guide.md "The command line"): a
// code is selected by its key flag (--zone UBC 1976, --av/--map-area ATC 3-06, --ubc97-zone UBC
// 1997, --sds ASCE 7-22,
// --ag EC8); its other inputs are then required or take the code's documented default.

#include "app/cli/Args.h"
#include "core/codes/CodeSet.h"
#include "core/io/Project.h"

#include <set>
#include <string>

namespace kinstab::cli {

std::set<std::string> buildingFlagNames();
std::set<std::string> buildingSwitchNames();
// Throws UsageError naming the flag.
Building buildingFromFlags(const Args& args);
CodeSelection codesFromFlags(const Args& args);
// A core validation message, prefixed with the flag that carries the bad field.
UsageError inputUsageError(const InputError& e);
// Loads --project FILE; a broken file is a UsageError naming the file and the field.
Project projectFromFlag(const Args& args);
// The flag that carries a core field ("ubc1976.zone" → "--zone"), empty when none.
std::string flagForField(const std::string& message);

} // namespace kinstab::cli
