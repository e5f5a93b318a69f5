// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/slab/RecordRun.h"

#include "core/excitation/RecordedMotion.h"
#include "core/slab/ExactSolver.h"

namespace kinstab {

SlabResult runRecord1D(const Slab1DCase& c, const Accelerogram& motion, double peak,
                       const RunOptions& options, SlabRecorder* recorder) {
    // One run's own view: formed only as far as the run reaches.
    return runRecord1D(c, std::make_shared<const RecordSamples>(motion, c.tstar), peak, options,
                       recorder);
}

SlabResult runRecord1D(const Slab1DCase& c, // its tstar built the samples
                       std::shared_ptr<const RecordSamples> samples, double peak,
                       const RunOptions& options, SlabRecorder* recorder) {
    return solveExact(RecordedMotion(std::move(samples), peak), c.slab, options, recorder);
}

} // namespace kinstab
