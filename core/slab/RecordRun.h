// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The 1-DOF slab under a recorded motion scaled to a peak (docs/theory.md §3, §7): the run an
// engineer asks for when a record, not the enveloped sine, is the excitation. Only the exact solver
// runs records (it is exact for the linearly interpolated samples, docs/theory.md §6).

#include "core/records/Accelerogram.h"
#include "core/slab/Slab1DCase.h"

#include <memory>

namespace kinstab {

class RecordSamples;

// peak: the peak |a| (g) the motion is scaled to. Throws std::invalid_argument on a bad motion.
// recorder: what is kept beyond the result (core/slab/SlabRecorder.h); null: nothing.
SlabResult runRecord1D(const Slab1DCase& c, const Accelerogram& motion, double peak,
                       const RunOptions& options = {}, SlabRecorder* recorder = nullptr);
// The same run on samples built once for c.tstar (core/excitation/RecordedMotion.h): what every
// run of a critical search uses, bit for bit the run above.
SlabResult runRecord1D(const Slab1DCase& c, std::shared_ptr<const RecordSamples> samples,
                       double peak, const RunOptions& options = {},
                       SlabRecorder* recorder = nullptr);

} // namespace kinstab
