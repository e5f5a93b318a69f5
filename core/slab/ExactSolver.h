// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Event-driven exact solver of the 1-DOF slab (docs/theory.md §4, §6; docs/theory.md §6.1-§6.3).
// Between events the slip is a pure quadrature of a(tau) with closed-form integrals, so nothing
// is integrated numerically. Events are located on brackets that cannot miss them:
//  - slip onset is a time-only event, |a| = mu: all its roots come from per-segment crossings;
//  - between consecutive roots of |a| = mu the slip velocity is monotone, so each such piece
//    holds at most one stop, and the slip displacement is monotone, so at most one collapse.

#include "core/excitation/Excitation1D.h"
#include "core/slab/SlabRecorder.h"
#include "core/slab/SlabTypes.h"

namespace kinstab {

// recorder: what is kept beyond the result (core/slab/SlabRecorder.h); null: nothing.
SlabResult solveExact(const Excitation1D& excitation, const SlabParams& params,
                      const RunOptions& options = {}, SlabRecorder* recorder = nullptr);

} // namespace kinstab
