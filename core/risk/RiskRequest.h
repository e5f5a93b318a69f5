// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What kinstab-cli risk and Python's kinstab.risk ask for, declared once: the inputs, their
// ranges and which go together. A problem comes back by key ({key, value, why}); each front end
// renders the keys its own way ("--target-rate" on the command line, "target_rate=" in Python),
// including the keys a why names in braces ("needs {beta}").

#include "core/io/StudyJson.h"
#include "core/risk/HazardFile.h"
#include "core/risk/RiskAnalysis.h"
#include "core/study/Fragility.h"

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

namespace kinstab {

struct RiskRequest {
    std::string hazard; // the hazard file
    HazardFormat format = HazardFormat::Auto;
    std::optional<HazardSite> site;
    std::optional<std::string> results; // study results (JSONL): a fragility per parameter set
    std::optional<std::size_t> set;     // of the results; none: every set
    std::optional<double> median, beta; // a fragility given by its numbers, g and dispersion
    std::optional<std::string> measure; // of that fragility: "pga", "sa(1s/5%)" or "SA(1.0)"
    RiskSettings settings;
    BootstrapSettings bootstrap; // of a set's fragility; its level is not used (5/50/95 %)
};

// The largest exposure asked about, as the project file declares it (core/io/StudyJson.h).
inline constexpr double kMaxRiskYears = kMaxProjectHazardYears;
inline constexpr std::size_t kMaxRiskResamples = 100'000; // as kinstab-cli fragility

struct RiskProblem {
    std::string key;             // "median", "target_rate", ...
    std::optional<double> value; // the bad number, when a number is bad
    std::string why;             // may name other keys in braces: "needs {beta}"
};

// None when the request can run.
std::optional<RiskProblem> riskRequestProblem(const RiskRequest& r);
// The measure a --measure text names (the study's, OpenQuake's or the USGS's spelling).
std::optional<HazardMeasure> measureFromText(const std::string& text);
// why with every {key} replaced by name(key).
std::string renderRiskKeys(const std::string& why,
                           const std::function<std::string(const std::string&)>& name);

} // namespace kinstab
