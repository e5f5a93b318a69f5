// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The keys that say which case a result was computed for (model, solver, envelope, μ, t*, limit;
// the planar model's own inputs), written the same way by kinstab-cli and by the GUI's export.

#include "core/slab/PlanarCase.h"
#include "core/slab/Slab1DCase.h"

#include <nlohmann/json.hpp>

namespace kinstab {

// The "envelope" object: name, α, β, the τ's γc uses, the τ's computed, the scale.
nlohmann::json envelopeJson(const Slab1DCase& c);
// model "slab1d", solver, envelope, mu, tstar, limit.
nlohmann::json slab1DCaseJson(const Slab1DCase& c);
// model "planar", solver and tolerances, envelope, mu, tstar, limit, theta, ay_ratio, fy,
// normalization, vertical (null: gravity only).
nlohmann::json planarCaseJson(const PlanarCase& c);

} // namespace kinstab
