// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The model flags shared by simulate, surface and critical (docs/user-guide.md "The command line").

#include "app/cli/Args.h"
#include "core/base/ModelKind.h"
#include "core/io/CaseJson.h"
#include "core/slab/Slab1DCase.h"

#include <nlohmann/json.hpp>
#include <set>

namespace kinstab::cli {

// --model slab1d|planar (default slab1d); throws UsageError naming the flag and the value.
ModelKind modelFromFlags(const Args& args);
// Flags every model command accepts.
std::set<std::string> modelFlagNames();
// Reads and validates the 1-DOF case; throws UsageError naming the bad flag.
// allowRecord: --record/--floor-period/--damping are read by the caller (simulate only).
Slab1DCase slab1DCaseFromFlags(const Args& args, bool allowRecord = false);
// The flags both models share (envelope, t*, mu, limit, scale, duration, solver), unchecked
// against the model.
Slab1DCase commonCaseFromFlags(const Args& args);

} // namespace kinstab::cli
