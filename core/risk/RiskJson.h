// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The JSON of kinstab-cli risk and Python's kinstab.risk (docs/studies.md, "Risk"): keys are the
// public interface (added, never renamed). A number that is not finite is never written: a
// result holding one throws InternalError naming its key.

#include "core/risk/RiskAnalysis.h"
#include "core/study/Fragility.h"

#include <nlohmann/json.hpp>

#include <string>

namespace kinstab {

// The rule of core/risk/RiskIntegral.h in words, as every output states it.
extern const char* const kRiskIntegrationRule;

// file: as given; measureChecked: the fragility's measure was compared with the curve's.
nlohmann::ordered_json hazardJson(const HazardCurve& c, const std::string& file,
                                  bool measureChecked);
// lambda_c, p_collapse_in_years, integration, the closed forms and the targets.
nlohmann::ordered_json riskResultJson(const HazardCurve& c, const RiskResult& r,
                                      const RiskSettings& s);
nlohmann::ordered_json riskBootstrapJson(const RiskBootstrap& b, const BootstrapSettings& s);
// Throws InternalError "risk: non-finite KEY" for a NaN or infinity anywhere in j.
void requireFiniteJson(const nlohmann::ordered_json& j, const std::string& path = "risk");

} // namespace kinstab
