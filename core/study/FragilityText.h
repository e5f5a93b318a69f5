// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Fragility results as JSON (everything: fit, bounds, points, curve) and as CSV (one line per
// parameter set), with locale-independent numbers.

#include "core/study/Fragility.h"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace kinstab {

nlohmann::ordered_json fragilityJson(const std::vector<Fragility>& sets,
                                     const BootstrapSettings& b);
// Text cells (measure, motion) quoted as RFC 4180 asks, a leading = + - @ neutralised.
std::string fragilityCsv(const std::vector<Fragility>& sets);

} // namespace kinstab
