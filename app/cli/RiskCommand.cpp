// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli risk: the annual rate and the probability in N years of the slab falling, from a
// site's hazard curve and a collapse fragility (docs/studies.md, "Risk"). The request is core's
// (core/risk/RiskRequest.h); here its keys become flags.

#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "core/base/TextInput.h"
#include "core/io/JsonText.h"
#include "core/io/StudyRowJson.h"
#include "core/risk/RiskReport.h"

#include <algorithm>
#include <utility>

namespace kinstab::cli {

namespace {

std::string flagOf(std::string key) {
    std::replace(key.begin(), key.end(), '_', '-');
    return "--" + key;
}

// "--median '-1': must be > 0 and at most 1000 g", the flag's text as typed.
UsageError usageError(const RiskProblem& p, const Args& args) {
    const std::string flag = flagOf(p.key);
    const std::string typed = args.optionalText(flag.substr(2)).value_or("");
    return UsageError(flag + (args.has(flag.substr(2)) ? " " + quotedToken(typed) : "") + ": " +
                      renderRiskKeys(p.why, flagOf));
}

HazardSite siteFrom(const std::string& text) {
    const std::size_t comma = text.find(',');
    const auto lon = parseDouble(text.substr(0, comma));
    const auto lat =
        comma == std::string::npos ? std::nullopt : parseDouble(text.substr(comma + 1));
    if (!lon || !lat)
        throw UsageError("--site " + quotedToken(text) + ": expected LON,LAT in degrees");
    return {*lon, *lat};
}

RiskRequest requestFrom(const Args& args) {
    RiskRequest r;
    r.hazard = args.text("hazard");
    r.format = *hazardFormatFromName(
        args.choice("hazard-format", {"auto", "openquake", "usgs", "csv"}, "auto"));
    if (const auto s = args.optionalText("site")) r.site = siteFrom(*s);
    r.results = args.optionalText("results");
    if (const auto k = args.optionalText("set")) {
        r.set = parseCount(*k, 1'000'000'000);
        if (!r.set) throw UsageError("--set " + quotedToken(*k) + ": must be a set number >= 0");
    }
    r.median = args.optionalNumber("median");
    r.beta = args.optionalNumber("beta");
    r.measure = args.optionalText("measure");
    r.settings.years = args.number("years", r.settings.years);
    r.settings.targetRate = args.number("target-rate", r.settings.targetRate);
    r.settings.imG = args.optionalNumber("im");
    const std::string resamples = args.text("bootstrap", "1000");
    const auto n = parseCount(resamples, kMaxRiskResamples);
    if (!n) throw UsageError("--bootstrap " + quotedToken(resamples) + ": must be 0 to 100000");
    r.bootstrap.resamples = *n;
    const std::string seed = args.text("seed", "1");
    const auto s = parseCount(seed, 1'000'000'000'000ull);
    if (!s) throw UsageError("--seed " + quotedToken(seed) + ": must be a whole number >= 0");
    r.bootstrap.seed = *s;
    return r;
}

} // namespace

int runRisk(const ArgList& argv) {
    const Args args(argv, {"hazard", "hazard-format", "site", "results", "set", "median", "beta",
                           "measure", "years", "target-rate", "im", "bootstrap", "seed", "o"});
    const RiskRequest r = requestFrom(args);
    if (const auto o = args.optionalText("o")) checkOutputPath("o", *o);
    nlohmann::ordered_json j;
    try {
        j = riskReport(r);
    } catch (const RiskRequestError& e) {
        throw usageError(e.problem, args);
    } catch (const HazardError& e) {
        throw UsageError("--hazard " + std::string(e.what()));
    } catch (const StudyRowError& e) {
        throw UsageError("--results " + std::string(e.what()));
    }
    writeOutput(args, "o", jsonText(std::move(j), 2) + "\n");
    return 0;
}

} // namespace kinstab::cli
