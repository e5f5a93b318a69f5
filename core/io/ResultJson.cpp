// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/ResultJson.h"

#include "core/base/InternalError.h"

#include <cmath>
#include <sstream>

namespace kinstab {

nlohmann::json numberOrNull(double x) {
    return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json();
}

namespace {
// A number the output promises: a NaN or infinity here is a bug upstream, refused rather than
// written as null (which a reader would take for "no collapse" or "not computed").
double promised(double x, const std::string& what) {
    if (!std::isfinite(x)) {
        std::ostringstream s;
        s << what << " = " << x << " where the output promises a number";
        throw InternalError(s.str());
    }
    return x;
}

std::string pointName(const SweepResult& r, std::size_t i, std::size_t j) {
    std::ostringstream s;
    s.precision(17);
    s << "sweep point A = " << r.grid.amplitudes[i] << " g, f = " << r.grid.frequencies[j]
      << " Hz: tau_c";
    return s.str();
}
} // namespace

nlohmann::json workJson(const SolverWork& w) {
    return {{"accel_evaluations", w.accelEvaluations},
            {"root_iterations", w.rootIterations},
            {"steps", w.steps},
            {"events", w.events},
            {"restarts", w.restarts}};
}

nlohmann::json eventsJson(const std::vector<SlabEvent>& events) {
    nlohmann::json a = nlohmann::json::array();
    for (std::size_t i = 0; i < events.size(); ++i) {
        const SlabEvent& e = events[i];
        const std::string at = "event " + std::to_string(i) + " (" + eventKindName(e.kind) + ") ";
        a.push_back({{"tau", promised(e.tau, at + "tau")},
                     {"kind", eventKindName(e.kind)},
                     {"delta", promised(e.delta, at + "delta")},
                     {"velocity", promised(e.velocity, at + "velocity")},
                     {"direction", e.direction}});
    }
    return a;
}

nlohmann::json slabResultJson(const SlabResult& r, double tauRef) {
    const bool collapsed = r.outcome == Outcome::Collapsed;
    // A failed run promises no numbers (they are null where not finite); any other does, but
    // gamma_c only when there is a reference time (a record run may have none).
    auto number = [&](double x, const char* what) {
        return r.outcome == Outcome::Failed ? numberOrNull(x) : nlohmann::json(promised(x, what));
    };
    nlohmann::json j = {{"outcome", outcomeName(r.outcome)},
                        {"tau_c", collapsed ? number(r.tauC, "tau_c") : nlohmann::json()},
                        {"gamma_c", !collapsed              ? nlohmann::json(0.0)
                                    : std::isfinite(tauRef) ? number(tauRef / r.tauC, "gamma_c")
                                                            : nlohmann::json()},
                        {"slip_intervals", r.slipIntervals},
                        {"max_abs_delta", number(r.maxAbsDelta, "max_abs_delta")},
                        {"residual_delta", number(r.residualDelta, "residual_delta")},
                        {"tau_end", number(r.tauEnd, "tau_end")},
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
            tr.push_back(collapsed ? nlohmann::json(promised(p.tauC, pointName(r, i, j)))
                                   : nlohmann::json());
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
            if (collapsed) s << promised(p.tauC, pointName(r, i, j));
            s << ',' << (collapsed ? tauRef / p.tauC : 0.0) << '\n';
        }
    return s.str();
}

} // namespace kinstab
