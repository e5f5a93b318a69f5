// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Work-precision study of the planar solver (issue 22): for a fixed set of planar cases, the
// error of the adaptive planar solver at a sweep of tolerances against a reference at its
// tightest tolerance, and the run time. Rows have the 1-DOF study's shape (WorkPrecisionRow), so
// both go in one CSV and one plot.
// The reference is checked by an independent method: Moreau's proximal implicit Euler
// (core/slab/MoreauSolver2D.h) at steps h and h/2 with Richardson extrapolation, which locates
// no events at all; the study reports the largest relative difference of tau_c between the two.

#include "core/excitation/Excitation1D.h"
#include "core/precision/WorkPrecision.h"
#include "core/slab/PlanarCase.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace kinstab {

struct PlanarPrecisionCase {
    std::string id;
    std::string description;
    PlanarCase model;               // solver options unused
    std::vector<double> amplitudes; // A_x in g; every amplitude is one run
    double fxHz = 1.0;
};

// verticalUp: the RSN68 UP vertical motion for the case that needs it (null: that case is left
// out). The others: the benchmark case (f_y 1 Hz) and a collapse along the walls.
std::vector<PlanarPrecisionCase>
planarPrecisionCases(std::shared_ptr<const Excitation1D> verticalUp);

// Relative tolerances of the sweep (absolute = relative / 100), loosest first.
std::vector<double> planarPrecisionTolerances();

struct PlanarPrecisionStudy {
    std::vector<PlanarPrecisionCase> cases;
    std::vector<WorkPrecisionRow> rows; // solver "planar", setting "rtol=1e-08"
    std::string reference;              // how the reference is made
    // Max over collapsed reference runs of |tau_c(ref) - tau_c(Moreau, Richardson)| / tau_c.
    double referenceCheck = 0;
    double moreauStep = 0; // the finer Moreau step (tau)
};

struct PlanarPrecisionOptions {
    int repeats = 5;
    std::shared_ptr<const Excitation1D> verticalUp;
    std::function<void(std::size_t, std::size_t)> onProgress; // may be empty
};

PlanarPrecisionStudy runPlanarPrecisionStudy(const PlanarPrecisionOptions& options);
std::string planarPrecisionText(const PlanarPrecisionStudy& s);

} // namespace kinstab
