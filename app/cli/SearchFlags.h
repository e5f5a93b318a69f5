// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The critical-amplitude search flags shared by `critical` and `simulate --record --critical`:
// --max-amplitude A (5 g), --scan-step S (0.01 g), --tolerance T (1e-6 g).

#include "app/cli/Args.h"
#include "core/sweep/CriticalAmplitude.h"

#include <set>
#include <string>

namespace kinstab::cli {

std::set<std::string> searchFlagNames();
CriticalSearch criticalSearchFromFlags(const Args& args); // throws UsageError naming the flag

} // namespace kinstab::cli
