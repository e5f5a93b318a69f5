// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The results of one run as Python sees them: SimulationResult (1-DOF) and PlanarResult.

#include "core/slab/History.h"
#include "core/slab/PlanarSolver.h"
#include "core/slab/PointResult.h"
#include "core/slab/SlabTypes.h"

#include <pybind11/pybind11.h>

#include <optional>
#include <vector>

namespace kinstab::python {

// Each keeps where it ran (amplitude, frequency, tau_ref) as RunPoint.
struct SlabRun : RunPoint {
    SlabResult result;
    std::optional<std::vector<SlabEvent>> events; // when asked for
    std::optional<History> history;
};

struct PlanarRun : RunPoint {
    PlanarResult result;
    PlanarEventLog events; // when asked for
    PlanarPathLog path;    // when asked for
};

// tau_c where the slab collapsed, NaN otherwise; gamma_c = tau_ref / tau_c, 0 otherwise (the
// CLI's JSON: null and 0).
double collapseTau(const SlabResult& r);
double gammaC(const SlabResult& r, double tauRef);
pybind11::dict workDict(const SolverWork& w);
pybind11::dict slabEventArrays(const std::vector<SlabEvent>& events);
pybind11::dict historyArrays(const History& h);

void bindRunResults(pybind11::module_& m);

} // namespace kinstab::python
