#include "core/io/ResultJson.h"

#include <cmath>
#include <sstream>

namespace kinstab {

nlohmann::json numberOrNull(double x) {
    return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json();
}

nlohmann::json workJson(const SolverWork& w) {
    return {{"accel_evaluations", w.accelEvaluations},
            {"root_iterations", w.rootIterations},
            {"steps", w.steps},
            {"events", w.events},
            {"restarts", w.restarts}};
}

nlohmann::json eventsJson(const std::vector<SlabEvent>& events) {
    nlohmann::json a = nlohmann::json::array();
    for (const auto& e : events)
        a.push_back({{"tau", e.tau},
                     {"kind", eventKindName(e.kind)},
                     {"delta", e.delta},
                     {"velocity", e.velocity},
                     {"direction", e.direction}});
    return a;
}

nlohmann::json slabResultJson(const SlabResult& r, double tauRef) {
    nlohmann::json j = {{"outcome", outcomeName(r.outcome)},
                        {"tau_c", numberOrNull(r.outcome == Outcome::Collapsed ? r.tauC : NAN)},
                        {"gamma_c", r.outcome == Outcome::Collapsed ? tauRef / r.tauC : 0.0},
                        {"slip_intervals", r.slipIntervals},
                        {"max_abs_delta", r.maxAbsDelta},
                        {"residual_delta", r.residualDelta},
                        {"tau_end", r.tauEnd},
                        {"work", workJson(r.work)}};
    if (r.outcome == Outcome::LiftOff) j["tau_lift_off"] = numberOrNull(r.tauC);
    if (r.outcome == Outcome::Failed) j["failure"] = r.failure;
    return j;
}

nlohmann::json sweepJson(const SweepResult& r, double tauRef) {
    nlohmann::json tau = nlohmann::json::array(), gamma = nlohmann::json::array(),
                   outcome = nlohmann::json::array();
    for (std::size_t i = 0; i < r.grid.amplitudes.size(); ++i) {
        nlohmann::json tr = nlohmann::json::array(), gr = nlohmann::json::array(),
                       orow = nlohmann::json::array();
        for (std::size_t j = 0; j < r.grid.frequencies.size(); ++j) {
            const std::size_t k = i * r.grid.frequencies.size() + j;
            const PointResult& p = r.points[k];
            const bool collapsed = r.done[k] && p.outcome == Outcome::Collapsed;
            tr.push_back(numberOrNull(collapsed ? p.tauC : NAN));
            gr.push_back(collapsed ? tauRef / p.tauC : 0.0);
            orow.push_back(r.done[k] ? outcomeName(p.outcome) : "not_run");
        }
        tau.push_back(tr);
        gamma.push_back(gr);
        outcome.push_back(orow);
    }
    return {{"tau_ref", tauRef},
            {"amplitudes", r.grid.amplitudes},
            {"frequencies", r.grid.frequencies},
            {"tau_c", tau},
            {"gamma_c", gamma},
            {"outcome", outcome},
            {"completed", r.completed},
            {"wall_time_s", r.wallTimeSeconds}};
}

std::string sweepCsv(const SweepResult& r, double tauRef) {
    std::ostringstream s;
    s.precision(12);
    s << "amplitude_g,frequency_hz,outcome,tau_c,gamma_c\n";
    for (std::size_t i = 0; i < r.grid.amplitudes.size(); ++i)
        for (std::size_t j = 0; j < r.grid.frequencies.size(); ++j) {
            const std::size_t k = i * r.grid.frequencies.size() + j;
            const PointResult& p = r.points[k];
            const bool collapsed = r.done[k] && p.outcome == Outcome::Collapsed;
            s << r.grid.amplitudes[i] << ',' << r.grid.frequencies[j] << ','
              << (r.done[k] ? outcomeName(p.outcome) : "not_run") << ',';
            if (collapsed) s << p.tauC;
            s << ',' << (collapsed ? tauRef / p.tauC : 0.0) << '\n';
        }
    return s.str();
}

} // namespace kinstab
