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
// What names a parameter set: set, mu, tstar, limit, floor_period_s, floor_damping and, when the
// study uses them, level and motion (the first keys of each set in fragilityJson).
nlohmann::ordered_json fragilityParametersJson(const StudyRow& parameters);
// Text cells (measure, motion) quoted as RFC 4180 asks, a leading = + - @ neutralised.
std::string fragilityCsv(const std::vector<Fragility>& sets);

} // namespace kinstab
