// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/RockingJson.h"

#include "core/io/JsonValue.h"
#include "core/io/RecordJson.h"

#include <string>

namespace kinstab {

using nlohmann::json;

json rockingModelJson(const RockingModel& m) {
    return {{"half_width_m", m.block.halfWidth},
            {"half_height_m", m.block.halfHeight},
            {"alpha_rad", blockAlpha(m.block)},
            {"radius_m", blockRadius(m.block)},
            {"p_rad_s", blockFrequency(m.block)},
            {"restitution", restitutionOf(m)},
            {"restitution_source", m.restitution ? "given" : "housner"},
            {"equations", m.equations == RockingEquations::Exact ? "exact" : "linear"},
            {"initial_tilt", m.initialTilt},
            {"mu", orNull(m.mu)},
            {"duration_s", orNull(m.duration)}};
}

json rockingResultJson(const RockingResult& r) {
    return {{"outcome", std::string(rockingOutcomeName(r.outcome))},
            {"max_theta_over_alpha", r.maxThetaOverAlpha},
            {"impact_times_s", r.impactTimes},
            {"impacts", r.impactTimes.size()},
            {"overturn_time_s", orNull(r.overturnTime)},
            {"leaves_base_time_s", orNull(r.leavesBaseTime)},
            {"sliding_displacement_m", r.slidingDisplacement},
            {"max_sliding_m", r.maxSliding},
            {"end_time_s", r.endTime},
            {"steps", r.steps},
            {"events", r.events}};
}

json pulseExcitationJson(const Pulse& p) {
    json j = {{"kind", "pulse"},
              {"shape", std::string(pulseShapeName(p.shape))},
              {"amplitude_g", p.amplitude}};
    if (p.shape == PulseShape::Rectangular)
        j["duration_s"] = p.durationS;
    else
        j["frequency_hz"] = p.frequencyHz;
    return j;
}

json sineExcitationJson(const Envelope& env, double amplitude, double frequency, double endS) {
    return {{"kind", "enveloped-sine"},    {"amplitude_g", amplitude},  {"frequency_hz", frequency},
            {"envelope_alpha", env.alpha}, {"envelope_beta", env.beta}, {"end_s", endS}};
}

json recordExcitationJson(const Accelerogram& motion, double scaledPeak, std::optional<int> level,
                          const Accelerogram* vertical) {
    json j = accelerogramJson(motion);
    j["kind"] = "record";
    j["scaled_peak_g"] = scaledPeak;
    if (level) j["level"] = *level;
    if (vertical) j["vertical"] = accelerogramJson(*vertical);
    return j;
}

json overturningSearchJson(const OverturningIntervals& iv, const OverturningSearch& s) {
    json intervals = json::array();
    for (const auto& [from, to] : iv.intervals)
        intervals.push_back({from, to});
    return {{"critical_amplitude_g", orNull(iv.critical())},
            {"overturning_intervals_g", intervals},
            {"max_amplitude_g", s.maxAmplitude},
            {"scan_points", s.scanPoints},
            {"tolerance", s.tolerance},
            {"refine_depth", s.refineDepth},
            {"max_runs", s.maxRuns},
            {"critical_runs", iv.runs},
            {"critical_run_limit_reached", iv.runLimitReached}};
}

json overturningMapJson(const OverturningMap& m) {
    json states = json::array(), theta = json::array();
    for (std::size_t i = 0; i < m.frequencies.size(); ++i) {
        json rowS = json::array(), rowT = json::array();
        for (std::size_t j = 0; j < m.amplitudes.size(); ++j) {
            const std::size_t k = m.at(static_cast<int>(i), static_cast<int>(j));
            rowS.push_back(m.overturns[k]);
            rowT.push_back(m.maxThetaOverAlpha[k]);
        }
        states.push_back(rowS);
        theta.push_back(rowT);
    }
    return {{"shape", std::string(pulseShapeName(m.spec.shape))},
            {"a_p_over_alpha_g", m.amplitudes},
            {"omega_p_over_p", m.frequencies},
            {"state_legend", {"survives", "overturns", "leaves-base"}},
            {"state", states},
            {"max_theta_over_alpha", theta},
            {"complete", m.complete}};
}

} // namespace kinstab
