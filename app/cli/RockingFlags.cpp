// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/RockingFlags.h"

namespace kinstab::cli {

std::set<std::string> rockingModelFlagNames() {
    return {"half-width", "half-height", "restitution", "mu", "initial-tilt", "duration"};
}

RockingModel rockingModelFromFlags(const Args& args) {
    for (const char* f : {"half-width", "half-height"})
        if (!args.has(f))
            throw UsageError(std::string("missing required flag --") + f + " (metres)");
    RockingModel m;
    m.block.halfWidth = args.input(kHalfWidthInput);
    m.block.halfHeight = args.input(kHalfHeightInput);
    m.restitution = args.optionalInput(kRestitutionInput);
    m.equations = args.has("linear") ? RockingEquations::Linearised : RockingEquations::Exact;
    m.mu = args.optionalInput(kBlockMuInput);
    m.initialTilt = args.input(kInitialTiltInput);
    m.duration = args.optionalInput(kRockingDurationInput);
    args.refuse(checkRockingModel(m));
    return m;
}

nlohmann::json rockingModelJson(const RockingModel& m) {
    nlohmann::json j = {{"half_width_m", m.block.halfWidth},
                        {"half_height_m", m.block.halfHeight},
                        {"alpha_rad", blockAlpha(m.block)},
                        {"radius_m", blockRadius(m.block)},
                        {"p_rad_s", blockFrequency(m.block)},
                        {"restitution", restitutionOf(m)},
                        {"restitution_source", m.restitution ? "given" : "housner"},
                        {"equations", m.equations == RockingEquations::Exact ? "exact" : "linear"},
                        {"initial_tilt", m.initialTilt}};
    j["mu"] = m.mu ? nlohmann::json(*m.mu) : nlohmann::json(nullptr);
    j["duration_s"] = m.duration ? nlohmann::json(*m.duration) : nlohmann::json(nullptr);
    return j;
}

nlohmann::json rockingResultJson(const RockingResult& r) {
    auto orNull = [](const std::optional<double>& x) {
        return x ? nlohmann::json(*x) : nlohmann::json(nullptr);
    };
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

} // namespace kinstab::cli
