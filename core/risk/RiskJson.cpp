// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/risk/RiskJson.h"

#include "core/base/InternalError.h"

#include <cmath>

namespace kinstab {

using ojson = nlohmann::ordered_json;

const char* const kRiskIntegrationRule =
    "lambda_c = integral of P(C|x) |d lambda(x)|: lambda(x) linear in log-log between the "
    "hazard curve's points, each segment integrated in closed form (no quadrature error); the "
    "rate beyond the last point, lambda(x_max), counted with P(C|x_max); intensities below the "
    "first point add no rate (lambda held at lambda(x_min))";

namespace {

// The ratio of a closed form to the integral, or null when the integral underflowed to 0 (or the
// ratio overflows).
ojson ratio(double x, double lambdaC) {
    const double r = x / lambdaC;
    return lambdaC > 0.0 && std::isfinite(r) ? ojson(r) : ojson();
}

ojson integrationJson(const HazardCurve& c, const RiskIntegral& i) {
    return {{"rule", kRiskIntegrationRule},
            {"range_g", {c.points.front().imG, c.points.back().imG}},
            {"points", c.points.size()},
            {"lambda_c_within_curve", i.withinCurve},
            {"rate_beyond_curve",
             {{"rate_above_last_point", c.points.back().annualRate},
              {"p_collapse_at_last_point", i.pAtLastPoint},
              {"lambda_c_above_last_point", i.beyondLastPoint},
              {"p_collapse_at_first_point", i.pAtFirstPoint}}}};
}

ojson firstOrderJson(const FirstOrderForm& f, double lambdaC) {
    if (!f.why.empty()) return {{"lambda_c", nullptr}, {"why", f.why}};
    return {{"lambda_c", f.lambdaC},
            {"ratio_to_integral", ratio(f.lambdaC, lambdaC)},
            {"k", f.k},
            {"k0", f.k0},
            {"lambda_at_median", f.lambdaAtMedian},
            {"fit_range_g", {f.fitLoG, f.fitHiG}},
            {"fit", "secant of the log-log curve between median e^-beta and median e^beta"},
            {"source", "Cornell et al. 2002: k0 median^-k exp(k^2 beta^2 / 2)"}};
}

ojson secondOrderJson(const SecondOrderForm& f, double lambdaC) {
    if (!f.why.empty()) return {{"lambda_c", nullptr}, {"why", f.why}};
    return {{"lambda_c", f.lambdaC},
            {"ratio_to_integral", ratio(f.lambdaC, lambdaC)},
            {"k0", f.k0},
            {"k1", f.k1},
            {"k2", f.k2},
            {"fit_range_g", {f.fitLoG, f.fitHiG}},
            {"fit_points", f.points},
            {"fit", "least squares of ln lambda on a quadratic in ln x, points within 2 beta of "
                    "ln median - k beta^2 (at least 3)"},
            {"source", "Vamvatsikos 2013: sqrt(q) k0^(1-q) lambda(median)^q "
                       "exp(q k1^2 beta^2 / 2), q = 1 / (1 + 2 k2 beta^2)"}};
}

} // namespace

ojson hazardJson(const HazardCurve& c, const std::string& file, bool measureChecked) {
    return {{"file", file},
            {"source", c.source},
            {"format", c.format},
            {"intensity_measure", hazardMeasureName(c.measure)},
            {"measure_checked", measureChecked},
            {"points", c.points.size()},
            {"range_g", {c.points.front().imG, c.points.back().imG}},
            {"annual_rate_range", {c.points.back().annualRate, c.points.front().annualRate}},
            {"zero_rate_points_dropped", c.zeroRatePointsDropped}};
}

ojson riskResultJson(const HazardCurve& c, const RiskResult& r, const RiskSettings& s) {
    const double lc = r.integral.lambdaC;
    ojson j = {{"lambda_c", lc},
               {"p_collapse_in_years", {{"years", s.years}, {"p", r.pInYears}}},
               {"integration", integrationJson(c, r.integral)}};
    j["closed_form_first_order"] = firstOrderJson(r.firstOrder, lc);
    j["closed_form_second_order"] = secondOrderJson(r.secondOrder, lc);
    j["target_rate"] = s.targetRate;
    j["meets_target_rate"] = lc <= s.targetRate;
    if (r.targeted.medianG) {
        j["risk_targeted_median_g"] = *r.targeted.medianG;
    } else {
        j["risk_targeted_median_g"] = nullptr;
        j["risk_targeted_median_why"] = r.targeted.why;
    }
    j["im_at_p10_g"] = r.imAtTenPercent;
    if (r.pAtIm)
        j["p_collapse_at_im"] = {{"im_g", *s.imG},
                                 {"p", *r.pAtIm},
                                 {"target", kTargetConditionalProbability},
                                 {"within_target", *r.pAtIm <= kTargetConditionalProbability}};
    return j;
}

ojson riskBootstrapJson(const RiskBootstrap& b, const BootstrapSettings& s) {
    const auto p = [](const RiskPercentiles& x) {
        return ojson{{"p5", x.p5}, {"p50", x.p50}, {"p95", x.p95}};
    };
    return {{"resamples", b.resamples}, {"seed", s.seed},
            {"fitted", b.fitted},       {"unfitted_counted_as_zero", b.resamples - b.fitted},
            {"lambda_c", p(b.lambdaC)}, {"p_collapse_in_years", p(b.pInYears)}};
}

void requireFiniteJson(const ojson& j, const std::string& path) {
    if (j.is_number_float() && !std::isfinite(j.get<double>()))
        throw InternalError("risk: non-finite " + path);
    if (j.is_object())
        for (const auto& [key, value] : j.items())
            requireFiniteJson(value, path + "." + key);
    if (j.is_array())
        for (std::size_t i = 0; i < j.size(); ++i)
            requireFiniteJson(j[i], path + "[" + std::to_string(i) + "]");
}

} // namespace kinstab
