// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/FloorsJson.h"

#include "core/excitation/FloorFilter.h"
#include "core/io/JsonValue.h"

#include <locale>
#include <sstream>

namespace kinstab {

using nlohmann::json;

json floorSettingsToJson(const FloorSettings& s) {
    return {{"slab_level", orNull(s.slabLevel)},
            {"stiffness", stiffnessName(s.stiffness)},
            {"damping", s.damping},
            {"asce7_omega0", s.omega0},
            {"ec8_element_period_s", orNull(s.ec8ElementPeriod)}};
}

FloorSettings floorSettingsFromJson(const JsonReader& r) {
    FloorSettings s;
    s.slabLevel = r.optionalInteger("slab_level");
    const std::string stiffness = r.text("stiffness", stiffnessName(s.stiffness));
    const auto profile = stiffnessFromName(stiffness);
    if (!profile) r.fail("stiffness", "'" + stiffness + "': must be uniform or weight");
    s.stiffness = *profile;
    s.damping = r.number("damping", s.damping);
    s.omega0 = r.number("asce7_omega0", s.omega0);
    s.ec8ElementPeriod = r.optionalNumber("ec8_element_period_s");
    return s;
}

} // namespace kinstab

namespace kinstab {

namespace {

const FloorDemand* demandOf(const FloorAnalysis& a, const std::string& code) {
    for (const FloorDemand& d : a.demands)
        if (d.code == code) return &d;
    return nullptr;
}

json demandJson(const FloorDemand& d) {
    json trail = json::array();
    for (const TrailEntry& t : d.trail)
        trail.push_back(
            {{"name", t.name}, {"symbol", t.symbol}, {"value", t.value}, {"clause", t.clause}});
    return {{"code", d.code},          {"title", d.title}, {"slab_level", d.slabLevel},
            {"slab_pfa_g", d.slabPfa}, {"trail", trail},   {"notes", d.notes}};
}

json levelJson(const FloorAnalysis& a, const Building& b, std::size_t i) {
    const auto at = [&](const char* code, bool factor) {
        const FloorDemand* d = demandOf(a, code);
        return d ? json(factor ? d->factor[i] : d->pfa[i]) : json();
    };
    const bool searched = i < a.critical.size();
    return {{"level", i + 1},
            {"height", levelHeights(b)[i]},
            {"weight", levelWeights(b)[i]},
            {"pfa_g", a.pfa[i]},
            {"pfa_over_pga", a.pfa[i] / a.pga},
            {"asce7_22_hf", at("asce7_22", true)},
            {"asce7_22_pfa_g", at("asce7_22", false)},
            {"asce7_22_mce_pfa_g", at("asce7_22_mce", false)},
            {"ec8_pfa_g", at("ec8", false)},
            {"critical_floor_peak_g", searched ? orNull(a.critical[i].criticalFloorPeak) : json()},
            {"critical_pga_g", searched ? orNull(a.critical[i].criticalPga) : json()}};
}

} // namespace

json floorAnalysisJson(const FloorAnalysis& a, const Building& b) {
    json modes = json::array();
    for (const Mode& m : a.model.modes)
        modes.push_back({{"period_s", m.period},
                         {"participation", m.participation},
                         {"effective_mass", m.effectiveMass}});
    json levels = json::array();
    for (std::size_t i = 0; i < a.pfa.size(); ++i)
        levels.push_back(levelJson(a, b, i));
    json demands = json::array();
    for (const FloorDemand& d : a.demands)
        demands.push_back(demandJson(d));
    const FloorDemand* asce = demandOf(a, "asce7_22");
    long runs = 0;
    for (const LevelCritical& l : a.critical)
        runs += l.runs;
    return {{"period_s", a.building.period},
            {"period_source", a.building.periodSource},
            {"pga_g", a.pga},
            {"slab_level", a.slabLevel},
            {"modes", modes},
            {"asce7_22_ta_s", asce ? json(asce->trail.front().value) : json()},
            {"levels", levels},
            {"sdof_roof", {{"pfa_g", a.sdofRoofPeak}, {"pfa_over_pga", a.sdofRoofPeak / a.pga}}},
            {"demands", demands},
            {"runs", runs}};
}

std::string floorHistoryCsv(const FloorAnalysis& a, const Accelerogram& ground) {
    std::ostringstream s;
    s.imbue(std::locale::classic());
    s.precision(9);
    s << "t_s,ground_g";
    for (std::size_t i = 0; i < a.motions.size(); ++i)
        s << ",level_" << i + 1 << "_g";
    s << ",sdof_roof_g\n";
    const Accelerogram sdof = floorMotion(ground, {a.building.period, a.damping, std::nullopt});
    const std::size_t n = a.motions.empty() ? 0 : a.motions.front().size();
    for (std::size_t k = 0; k < n; ++k) {
        s << ground.dt * static_cast<double>(k) << ','
          << (k < ground.size() ? ground.samples[k] : 0.0);
        for (const Accelerogram& m : a.motions)
            s << ',' << m.samples[k];
        s << ',' << (k < sdof.size() ? sdof.samples[k] : 0.0) << '\n';
    }
    return s.str();
}

} // namespace kinstab
