// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A γc surface as a JSON result file: the sweep (core/io/ResultJson.h) with the case it was run
// for and, for the planar model, the side each collapse leaves by. kinstab-cli surface and the
// GUI's "Export surface" write this same object.

#include "core/slab/PlanarCase.h"
#include "core/slab/Slab1DCase.h"
#include "core/sweep/Sweep.h"

#include <nlohmann/json.hpp>

namespace kinstab {

nlohmann::json surfaceJson(const SweepResult& r, const Slab1DCase& c);
nlohmann::json surfaceJson(const SweepResult& r, const PlanarCase& c);

} // namespace kinstab
