// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/risk/RiskRequest.h"

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"

#include <cmath>

namespace kinstab {

namespace {

using Problem = std::optional<RiskProblem>;

Problem outside(const std::string& key, double x, double lo, double hi, const std::string& unit,
                bool openLow) {
    const bool low = openLow ? !(x > lo) : !(x >= lo);
    if (std::isfinite(x) && !low && x <= hi) return std::nullopt;
    return RiskProblem{key, x,
                       "must be " + std::string(openLow ? "> " : ">= ") + formatDouble(lo) +
                           " and at most " + formatDouble(hi) + unit};
}

Problem numberProblem(const RiskRequest& r) {
    if (r.median)
        if (auto p = outside("median", *r.median, 0.0, limits::kMaxAmplitudeG, " g", true))
            return p;
    if (r.beta)
        if (auto p = outside("beta", *r.beta, kMinFragilityBeta, kMaxFragilityBeta, "", false))
            return p;
    if (auto p = outside("years", r.settings.years, 0.0, kMaxRiskYears, " years", true)) return p;
    if (auto p = outside("target_rate", r.settings.targetRate, 0.0, 1.0, " per year", true))
        return p;
    if (r.settings.imG)
        if (auto p = outside("im", *r.settings.imG, 0.0, limits::kMaxAmplitudeG, " g", true))
            return p;
    if (r.site) {
        if (auto p = outside("site", r.site->lon, -180.0, 360.0, " degrees of longitude", false))
            return p;
        if (auto p = outside("site", r.site->lat, -90.0, 90.0, " degrees of latitude", false))
            return p;
    }
    if (r.bootstrap.resamples > kMaxRiskResamples)
        return RiskProblem{"bootstrap", double(r.bootstrap.resamples),
                           "must be 0 to " + std::to_string(kMaxRiskResamples)};
    return std::nullopt;
}

} // namespace

std::optional<HazardMeasure> measureFromText(const std::string& text) {
    if (auto m = measureFromStudy(text)) return m;
    if (auto m = measureFromOpenQuake(text)) return m;
    return measureFromUsgs(text);
}

std::optional<RiskProblem> riskRequestProblem(const RiskRequest& r) {
    if (r.hazard.empty()) return RiskProblem{"hazard", {}, "the hazard file is required"};
    if (r.results && (r.median || r.beta))
        return RiskProblem{
            "results", {}, "is a fragility per set: give either {results} or {median} and {beta}"};
    if (r.median && !r.beta) return RiskProblem{"median", r.median, "needs {beta}"};
    if (!r.results && !r.beta)
        return RiskProblem{"results",
                           {},
                           "give {results}, or {median} and {beta}, or {beta} alone for the "
                           "risk-targeted median"};
    if (r.set && !r.results) return RiskProblem{"set", double(*r.set), "needs {results}"};
    if (r.measure && r.results)
        return RiskProblem{"measure", {}, "a study's rows name their own measure"};
    if (r.measure && !measureFromText(*r.measure))
        return RiskProblem{"measure",
                           {},
                           quotedToken(*r.measure) + " is no measure a hazard curve is given in "
                                                     "(pga, sa(Ts/5%), PGA, SA(T), SA0P2)"};
    return numberProblem(r);
}

std::string renderRiskKeys(const std::string& why,
                           const std::function<std::string(const std::string&)>& name) {
    std::string out;
    for (std::size_t i = 0; i < why.size(); ++i) {
        const std::size_t close = why[i] == '{' ? why.find('}', i) : std::string::npos;
        if (close == std::string::npos) {
            out += why[i];
            continue;
        }
        out += name(why.substr(i + 1, close - i - 1));
        i = close;
    }
    return out;
}

} // namespace kinstab
