// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The "floors" object of a project (the floor-motion check's own inputs):
//   {"slab_level": null | 1..n, "stiffness": "uniform" | "weight", "damping": 0.05,
//    "asce7_omega0": 2.5, "ec8_element_period_s": null}
// Absent keys take the defaults of FloorSettings.

#include "core/building/FloorAnalysis.h"
#include "core/building/FloorSettings.h"
#include "core/io/JsonReader.h"

#include <nlohmann/json.hpp>

namespace kinstab {

nlohmann::json floorSettingsToJson(const FloorSettings& s);
FloorSettings floorSettingsFromJson(const JsonReader& r); // throws JsonFieldError

// The result of `kinstab-cli floors`: modes, asce7_22_ta_s, levels (bottom first, each with
// pfa_g, pfa_over_pga, the codes' demands and critical_pga_g), the SDOF roof comparison,
// demands with their trails and the verdicts at the slab's level. Absent values are null.
nlohmann::json floorAnalysisJson(const FloorAnalysis& a, const Building& b);

// t_s, ground_g, level_1_g ... level_n_g, sdof_roof_g: one row per sample (C locale).
std::string floorHistoryCsv(const FloorAnalysis& a, const Accelerogram& ground);

} // namespace kinstab
