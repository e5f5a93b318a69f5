// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/slab/RecordRun.h"

#include "core/excitation/RecordedMotion.h"
#include "core/slab/ExactSolver.h"

namespace kinstab {

SlabResult runRecord1D(const Slab1DCase& c, const Accelerogram& motion, double peak,
                       const RunOptions& options) {
    return solveExact(RecordedMotion(motion, c.tstar, peak), c.slab, options);
}

} // namespace kinstab
