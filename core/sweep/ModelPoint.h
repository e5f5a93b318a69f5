// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The point function of the model a sweep runs (docs/user-guide.md "model (1-DOF / planar)"), with
// where its A_crit scans start: the 1-DOF slab (nothing slips below mu) or, when a planar case is
// given, the planar slab of ch. VI on the same 1-DOF case (nothing slips below
// planarNoSlipAmplitude).

#include "core/slab/PlanarCase.h"
#include "core/slab/Slab1DCase.h"
#include "core/sweep/Sweep.h"

#include <optional>

namespace kinstab {

struct ModelPoint {
    PointFunction point;
    double scanFrom = 0; // criticalAmplitude's scanFrom: below it nothing slips
    double tauRef = 1;   // γc = tauRef / tau_c
};

ModelPoint modelPoint(const Slab1DCase& slab, const std::optional<PlanarInputs>& planar);

} // namespace kinstab
