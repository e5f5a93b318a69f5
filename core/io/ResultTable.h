// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A sweep as a plain-text table for terminals and logs: gamma_c with amplitudes down and
// frequencies across, "." where the slab stays on its walls.

#include "core/sweep/Sweep.h"

#include <string>

namespace kinstab {

std::string sweepTable(const SweepResult& r, double tauRef);

} // namespace kinstab
