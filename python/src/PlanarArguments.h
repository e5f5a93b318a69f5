// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The planar case (Furgerson 1980, ch. VI) from a 1-DOF case and keyword arguments, checked as
// kinstab-cli checks --model planar's flags (app/cli/PlanarFlags.cpp).

#include "core/slab/PlanarCase.h"
#include "core/slab/SlabInputs.h"

#include <optional>
#include <string>

namespace kinstab::python {

struct PlanarArguments {
    double fy = 1.0;
    double ayRatio = kAyRatioInput.fallback;
    double theta = kThetaInput.fallback;
    std::string normalization = "product";
    std::optional<std::string> vertical; // a record file of the upward acceleration
};

// Throws ValueError naming the keyword and value.
PlanarCase planarCaseFrom(const Slab1DCase& common, const PlanarArguments& a);

} // namespace kinstab::python
