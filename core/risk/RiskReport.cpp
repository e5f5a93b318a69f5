// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/risk/RiskReport.h"

#include "core/base/TextInput.h"
#include "core/io/FragilityText.h"
#include "core/io/StudyResults.h"
#include "core/risk/RiskJson.h"
#include "core/risk/SetRisk.h"

namespace kinstab {

namespace {

using ojson = nlohmann::ordered_json;

HazardCurve readCurve(const RiskRequest& r, const std::optional<HazardMeasure>& measure) {
    return readHazardFile(r.hazard, HazardRequest{r.format, r.site, measure});
}

ojson hazardOf(const HazardCurve& c, const RiskRequest& r,
               const std::optional<HazardMeasure>& measure) {
    return hazardJson(c, r.hazard, measure && c.measure.kind != HazardMeasure::Kind::Unstated);
}

// median and beta, or beta alone (the risk-targeted median).
ojson givenFragilityRisk(const RiskRequest& r) {
    const std::optional<HazardMeasure> m =
        r.measure ? measureFromText(*r.measure) : std::optional<HazardMeasure>();
    const HazardCurve c = readCurve(r, m);
    ojson j = {{"hazard", hazardOf(c, r, m)}};
    const double beta = *r.beta;
    std::optional<double> median = r.median;
    if (!median) {
        const RiskTargetedMedian t = riskTargetedMedian(c, beta, r.settings.targetRate);
        j["target_rate"] = r.settings.targetRate;
        j["risk_targeted_median_g"] = t.medianG ? ojson(*t.medianG) : ojson();
        if (!t.medianG) {
            j["risk_targeted_median_why"] = t.why;
            return j;
        }
        median = t.medianG;
    }
    j["fragility"] = {{"median_g", *median},
                      {"beta", beta},
                      {"given", r.median ? "median and beta" : "beta; the risk-targeted median"},
                      {"measure", m ? ojson(hazardMeasureName(*m)) : ojson()}};
    j.update(riskResultJson(c, analyzeRisk(c, {*median, beta}, r.settings), r.settings));
    return j;
}

// One parameter set of the results: its fitted fragility's risk and the bootstrap percentiles,
// or "no_fit".
ojson setRiskJson(const HazardCurve& c, const std::vector<StudyRow>& rows, const RiskRequest& r) {
    const SetRisk x = setRisk(c, rows, r.settings, r.bootstrap);
    const Fragility& f = x.fragility;
    ojson j = fragilityParametersJson(f.parameters);
    j["records"] = f.records;
    j["collapsed"] = f.collapsed;
    if (!x.risk) {
        j["no_fit"] = f.noFit;
        return j;
    }
    j["fragility"] = {{"median_g", f.fit->median},
                      {"beta", f.fit->beta},
                      {"measure", f.parameters.measure},
                      {"median_beyond_search", f.medianBeyondSearch},
                      {"beta_at_bound", f.betaAtBound}};
    j.update(riskResultJson(c, *x.risk, r.settings));
    if (x.bootstrap) j["bootstrap"] = riskBootstrapJson(*x.bootstrap, r.bootstrap);
    return j;
}

// The study's measure, as a hazard curve names it; a RiskRequestError when it has none.
HazardMeasure studyMeasure(const std::string& name) {
    const std::optional<HazardMeasure> m = measureFromStudy(name);
    if (!m)
        throw RiskRequestError({"results",
                                {},
                                "the study's intensity measure " + quotedToken(name) +
                                    " is no measure a hazard curve is given in (hazard curves "
                                    "are of PGA or 5 %-damped Sa)"});
    return *m;
}

ojson studyRisk(const RiskRequest& r) {
    std::optional<HazardCurve> curve; // read with the first set, whose rows name the measure
    std::optional<HazardMeasure> measure;
    std::string measureName;
    std::size_t sets = 0;
    ojson all = ojson::array(), picked;
    forEachStudySet(*r.results, [&](std::vector<StudyRow>&& rows) {
        if (!curve) {
            measureName = rows.front().measure;
            measure = studyMeasure(measureName);
            curve = readCurve(r, measure);
        }
        ++sets;
        if (r.set && rows.front().set != *r.set) return;
        if (r.set)
            picked = setRiskJson(*curve, rows, r);
        else
            all.push_back(setRiskJson(*curve, rows, r));
    });
    if (!curve) throw RiskRequestError({"results", {}, "the results file holds no rows"});
    if (r.set && picked.is_null())
        throw RiskRequestError({"set", double(*r.set),
                                "is no parameter set of the results (" + std::to_string(sets) +
                                    " sets, numbered from 0)"});
    if (r.set && picked.contains("no_fit"))
        throw RiskRequestError({"set", double(*r.set),
                                "has no fitted fragility: " + picked["no_fit"].get<std::string>()});
    ojson j = {{"hazard", hazardOf(*curve, r, measure)}};
    if (r.set) {
        j.update(picked);
        return j;
    }
    j["measure"] = measureName;
    j["sets"] = all;
    return j;
}

} // namespace

ojson riskReport(const RiskRequest& r) {
    if (std::optional<RiskProblem> p = riskRequestProblem(r)) throw RiskRequestError(*p);
    ojson j = r.results ? studyRisk(r) : givenFragilityRisk(r);
    requireFiniteJson(j);
    return j;
}

} // namespace kinstab
