// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/FrictionJson.h"

#include "core/io/JsonValue.h"
#include "core/io/ResultJson.h"

#include <cmath>

namespace kinstab {
namespace {

nlohmann::json curveJson(const TripletCurve& c) {
    return {{"delta_in", std::vector<double>(c.delta.begin(), c.delta.end())},
            {"shear_kips", std::vector<double>(c.shear.begin(), c.shear.end())}};
}

nlohmann::json coulombJson(const ConfigurationCalibration& c) {
    nlohmann::json points = nlohmann::json::array();
    for (const CoulombPoint& p : c.points)
        points.push_back({{"cp_psi", p.cpPsi}, {"V_inf", p.vInfKips}});
    nlohmann::json j = {{"configuration", c.configuration}, {"points", points}};
    if (!c.coulomb) {
        j["error"] = c.coulombError;
        return j;
    }
    const CoulombFit& f = *c.coulomb;
    j["points_used"] = f.points;
    j["bearing_area_in2"] = finiteOrNull(f.bearingAreaIn2);
    j["through_origin"] = {{"slope_kips_per_psi", f.slopeThroughOrigin},
                           {"mu_inf", finiteOrNull(f.muThroughOrigin)}};
    j["with_intercept"] = {{"slope_kips_per_psi", f.slopeWithIntercept},
                           {"intercept_kips", f.interceptKips},
                           {"mu_inf", finiteOrNull(f.muWithIntercept)}};
    return j;
}

nlohmann::json groupJson(const GroupCalibration& g) {
    nlohmann::json runs = nlohmann::json::array();
    for (const RunFit& r : g.runs) {
        nlohmann::json j = decayFitJson(r.fit);
        j["test"] = r.curve.test;
        j["excluded"] = r.excluded;
        runs.push_back(j);
    }
    nlohmann::json intervals = nlohmann::json::array();
    for (const SampleIntervals& s : g.intervals)
        intervals.push_back(intervalsJson(s));
    nlohmann::json fit = decayFitJson(g.fit);
    fit["fitted_kips"] = std::vector<double>(g.fit.fitted.begin(), g.fit.fitted.end());
    return {{"configuration", g.configuration},
            {"cp_psi", g.cpPsi},
            {"composite_tests", g.composite.test},
            {"composite", curveJson(g.composite)},
            {"fit", fit},
            {"runs", runs},
            {"outlier_test", g.outlier ? grubbsJson(*g.outlier) : nlohmann::json()},
            {"intervals", intervals}};
}

} // namespace

nlohmann::json decayFitJson(const DecayFit& f) {
    return {{"V1", f.v1},
            {"V_inf", f.vInf},
            {"c", f.c},
            {"b", f.b},
            {"beta", f.beta},
            {"alpha", f.alpha},
            {"f_m", f.fm},
            {"V_inf_upper_bound", f.vInfUpper},
            {"at_upper_bound", f.atUpperBound}};
}

nlohmann::json grubbsJson(const GrubbsResult& r) {
    return {{"test", "Grubbs"},         {"side", outlierSideName(r.side)},
            {"alpha", r.alpha},         {"n", r.n},
            {"suspect_index", r.index}, {"suspect_V_inf", r.value},
            {"mean", r.mean},           {"sd", r.sd},
            {"G", r.statistic},         {"G_critical", r.critical},
            {"rejected", r.rejected}};
}

nlohmann::json intervalsJson(const SampleIntervals& s) {
    return {{"tail", s.tail},
            {"n", s.n},
            {"mean", s.mean},
            {"variance", s.variance},
            {"sd", s.sd},
            {"mean_interval", {s.meanLower, s.meanUpper}},
            {"variance_interval", {s.varianceLower, s.varianceUpper}},
            {"sd_interval", {s.sdLower, s.sdUpper}},
            {"t_point", s.points.t},
            {"chi2_points", {s.points.chi2Lower, s.points.chi2Upper}}};
}

nlohmann::json frictionCalibrationJson(const FrictionCalibration& cal) {
    const CalibrationOptions& o = cal.options;
    nlohmann::json groups = nlohmann::json::array(), configs = nlohmann::json::array();
    for (const GroupCalibration& g : cal.groups)
        groups.push_back(groupJson(g));
    for (const ConfigurationCalibration& c : cal.configurations)
        configs.push_back(coulombJson(c));
    nlohmann::json options = {
        {"alpha", o.fit.alpha},
        {"betas", o.betas},
        {"max_cp_psi", o.maxCpPsi},
        {"bearing_area_in2", finiteOrNull(o.bearingAreaIn2)},
        {"outlier_test", "Grubbs"},
        {"outlier_alpha", o.outlierAlpha},
        {"outlier_side", outlierSideName(o.outlierSide)},
        {"exclude_outliers", o.excludeOutliers},
        {"xi_quadrature", "polyline V, exact W, Gauss-Legendre 8 with s = h t^3"}};
    return {{"options", options}, {"groups", groups}, {"configurations", configs}};
}

} // namespace kinstab
