// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A risk request answered (kinstab-cli risk, Python's kinstab.risk): the hazard file read, the
// fragility given or fitted per parameter set of the study results, and the JSON of
// core/risk/RiskJson.h:
//  - median and beta: the risk of that fragility;
//  - beta alone: the risk-targeted median for the target rate, and the risk of that fragility;
//  - results and a set: the risk of the set's fitted fragility, with bootstrap percentiles;
//  - results alone: "sets", one such object per parameter set.

#include "core/risk/RiskRequest.h"

#include <nlohmann/json.hpp>

#include <stdexcept>

namespace kinstab {

// A request whose inputs are each fine but cannot be answered, by key: a set the results do not
// hold or that has no fitted fragility.
struct RiskRequestError : std::runtime_error {
    explicit RiskRequestError(RiskProblem p)
        : std::runtime_error(p.key + ": " + p.why), problem(std::move(p)) {}
    RiskProblem problem;
};

// Throws RiskRequestError (riskRequestProblem's and the above), HazardError for the hazard file
// and StudyRowError for the results file, each naming where; InternalError for a result that is
// not finite.
nlohmann::ordered_json riskReport(const RiskRequest& r);

} // namespace kinstab
