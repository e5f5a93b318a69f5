// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The block flags of `kinstab-cli rocking`, `rocking-map` and `bench --rocking`
// (docs/theory.md §10):
//   --half-width B --half-height H (m) [--restitution E] [--linear] [--mu M]
//   [--initial-tilt R] [--duration S]

#include "app/cli/Args.h"
#include "core/rocking/RockingModel.h"

#include <set>
#include <string>

namespace kinstab::cli {

std::set<std::string> rockingModelFlagNames(); // valued flags; the switch is "linear"
// Throws UsageError naming the flag and value (--half-width and --half-height are required).
RockingModel rockingModelFromFlags(const Args& args);

} // namespace kinstab::cli
