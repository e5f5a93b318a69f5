// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/FragilityText.h"

#include "core/base/TextInput.h"
#include "core/io/JsonValue.h"
#include "core/io/StudyRowJson.h"

#include <cmath>
#include <string_view>

namespace kinstab {

using ojson = nlohmann::ordered_json;

namespace {

// Over the records that collapse; the censored ones counted.
ojson recordStatisticsJson(const RecordStatistics& s) {
    return {{"collapsed", s.collapsed},
            {"censored", s.censored},
            {"critical_im_mean_g", finiteOrNull<ojson>(s.meanG)},
            {"critical_im_median_g", finiteOrNull<ojson>(s.medianG)},
            {"critical_im_std_g", finiteOrNull<ojson>(s.stdG)},
            {"ln_critical_im_mean", finiteOrNull<ojson>(s.meanLn)},
            {"ln_critical_im_std", finiteOrNull<ojson>(s.stdLn)}};
}

ojson setJson(const Fragility& f) {
    ojson j = fragilityParametersJson(f.parameters);
    j["records"] = f.records;
    j["collapsed"] = f.collapsed;
    j["record_statistics"] = recordStatisticsJson(f.statistics);
    if (f.withoutFit > 0) j["records_without_fit"] = f.withoutFit;
    if (f.collapsedAsGiven) j["collapsed_as_given_fraction"] = *f.collapsedAsGiven;
    if (f.fit) {
        j["median_g"] = f.fit->median;
        j["beta"] = f.fit->beta;
        j["log_likelihood"] = f.fit->logLikelihood;
        // What the fit is: a median above every search limit is an extrapolation, a beta at
        // the search's bound is a bound.
        j["search_top_g"] = f.searchTop;
        j["median_beyond_search"] = f.medianBeyondSearch;
        j["beta_at_bound"] = f.betaAtBound;
        if (f.medianLower) {
            j["median_bounds_g"] = {finiteOrNull<ojson>(f.medianLower),
                                    finiteOrNull<ojson>(f.medianUpper)};
            j["median_upper_unbounded"] = !std::isfinite(*f.medianUpper);
        }
        if (f.betaLower) j["beta_bounds"] = {*f.betaLower, *f.betaUpper};
        j["bootstrap_fitted"] = f.fitted;
        j["bootstrap_unfitted"] = f.resamples - f.fitted; // counted as medians beyond the data
    } else {
        j["no_fit"] = f.noFit;
    }
    ojson points = ojson::array();
    for (const auto& pt : f.points)
        points.push_back({{"record", pt.record}, {"im_g", pt.intensity}, {"p", pt.probability}});
    j["points"] = points;
    ojson curve = ojson::array();
    for (const auto& c : f.curve)
        curve.push_back({{"im_g", c.intensity},
                         {"p", c.probability},
                         {"p_lower", finiteOrNull<ojson>(c.lower)},
                         {"p_upper", finiteOrNull<ojson>(c.upper)}});
    j["curve"] = curve;
    return j;
}

// A text cell: quoted when it holds a comma, quote or line break, and a leading = + - @ (which a
// spreadsheet would run as a formula) made plain text by a leading apostrophe. A number is
// never passed here, so numbers stay numbers.
std::string textCell(const std::string& s) {
    std::string t = s;
    if (!t.empty() && std::string_view("=+-@").find(t.front()) != std::string_view::npos)
        t.insert(t.begin(), '\'');
    if (t.find_first_of(",\"\r\n") == std::string::npos) return t;
    std::string q = "\"";
    for (char c : t)
        q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

std::string cell(const std::optional<double>& v) {
    return v && std::isfinite(*v) ? formatDouble(*v) : std::string();
}

} // namespace

// A period or damping that is not finite is written null either way: nlohmann's dump writes
// NaN and infinity as null.
ojson fragilityParametersJson(const StudyRow& p) {
    ojson j = {{"set", p.set}};
    addStudySetJson(j, p);
    return j;
}

ojson fragilityJson(const std::vector<Fragility>& sets, const BootstrapSettings& b) {
    ojson all = ojson::array();
    for (const Fragility& f : sets)
        all.push_back(setJson(f));
    return {{"measure", sets.empty() ? std::string() : sets.front().parameters.measure},
            {"bootstrap", {{"resamples", b.resamples}, {"seed", b.seed}, {"level", b.level}}},
            {"sets", all}};
}

namespace {

// The columns a study adds when it uses levels, motions or record scales (older studies keep
// their bytes): which of them the sets carry.
struct ExtraColumns {
    bool level = false, motion = false, asGiven = false, flags = false, block = false;
};

ExtraColumns extraColumns(const std::vector<Fragility>& sets) {
    ExtraColumns x;
    for (const Fragility& f : sets) {
        x.level = x.level || f.parameters.level.has_value();
        x.block = x.block || f.parameters.block.has_value();
        x.motion = x.motion || f.parameters.motion.has_value();
        x.asGiven = x.asGiven || f.collapsedAsGiven.has_value();
        x.flags = x.flags || f.medianBeyondSearch || f.betaAtBound;
    }
    return x;
}

std::string extraHeader(const ExtraColumns& x) {
    return std::string(x.level ? ",level" : "") + (x.motion ? ",motion" : "") +
           (x.asGiven ? ",collapsed_as_given_fraction" : "") +
           (x.flags ? ",median_beyond_search,beta_at_bound" : "") + (x.block ? ",block" : "");
}

std::string extraCells(const ExtraColumns& x, const Fragility& f) {
    const StudyRow& p = f.parameters;
    std::string out;
    if (x.level) out += "," + (p.level ? std::to_string(*p.level) : std::string());
    if (x.motion) out += "," + textCell(p.motion.value_or(""));
    if (x.asGiven) out += "," + cell(f.collapsedAsGiven);
    if (x.flags)
        out += std::string(f.medianBeyondSearch ? ",true" : ",false") +
               (f.betaAtBound ? ",true" : ",false");
    if (x.block) out += "," + textCell(p.block ? studyBlockText(*p.block) : std::string());
    return out;
}

} // namespace

std::string fragilityCsv(const std::vector<Fragility>& sets) {
    const ExtraColumns x = extraColumns(sets);
    std::string out = "set,mu,tstar,limit,floor_period_s,floor_damping,measure,records,collapsed,"
                      "median_g,beta,median_lower_g,median_upper_g,beta_lower,beta_upper" +
                      extraHeader(x) + "\n";
    for (const Fragility& f : sets) {
        const StudyRow& p = f.parameters;
        auto opt = [](bool has, double v) { return has ? std::optional(v) : std::nullopt; };
        // A block set has no slab: its mu, tstar and limit cells are empty (its block column).
        auto slab = [&p](double v) { return p.block ? std::string() : formatDouble(v); };
        out += std::to_string(p.set) + "," + slab(p.mu) + "," + slab(p.tstar) + "," +
               slab(p.limit) + "," + cell(p.floorPeriod) + "," + cell(p.floorDamping) + "," +
               textCell(p.measure) + "," + std::to_string(f.records) + "," +
               std::to_string(f.collapsed) + "," +
               cell(opt(f.fit.has_value(), f.fit ? f.fit->median : 0)) + "," +
               cell(opt(f.fit.has_value(), f.fit ? f.fit->beta : 0)) + "," + cell(f.medianLower) +
               "," + cell(f.medianUpper) + "," + cell(f.betaLower) + "," + cell(f.betaUpper) +
               extraCells(x, f) + "\n";
    }
    return out;
}

} // namespace kinstab
