// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/slab/History.h"

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"

#include <algorithm>
#include <cmath>
#include <locale>
#include <sstream>
#include <stdexcept>

namespace kinstab {

HistorySample stateAt(const Excitation1D& a, double mu, const std::vector<SlabEvent>& events,
                      double tau) {
    HistorySample s;
    s.tau = tau;
    s.accel = a.accel(tau);
    // Last event at or before tau.
    auto it = std::upper_bound(events.begin(), events.end(), tau,
                               [](double t, const SlabEvent& e) { return t < e.tau; });
    if (it == events.begin()) return s; // before the first slip: stuck at rest
    const SlabEvent& e = *std::prev(it);
    s.delta = e.delta;
    if (e.direction == 0 || e.kind == EventKind::Stick || e.kind == EventKind::Stable) return s;
    if (e.kind == EventKind::Collapse) {
        s.state = e.direction;
        return s;
    }
    const double h = tau - e.tau;
    const double dir = e.direction;
    s.state = e.direction;
    s.velocity = e.velocity - dir * mu * h - a.velocityChange(e.tau, tau);
    s.delta = e.delta + e.velocity * h - 0.5 * dir * mu * h * h - a.displacementChange(e.tau, tau);
    return s;
}

std::string validateHistoryStep(double tauEnd, double step) {
    if (!(step > 0.0) || !std::isfinite(step))
        return "step " + formatDouble(step) + ": must be > 0";
    if (!std::isfinite(tauEnd) || tauEnd < 0.0)
        return "the run's end " + formatDouble(tauEnd) + " is not a time";
    const double rows = std::floor(tauEnd / step) + 1.0;
    if (rows > static_cast<double>(limits::kMaxHistoryRows))
        return "step " + formatDouble(step) + " over the run's " + formatDouble(tauEnd) +
               " gives " + formatDouble(rows) + " rows, more than the limit of " +
               std::to_string(limits::kMaxHistoryRows) + "; the finest step here is " +
               formatDouble(tauEnd / static_cast<double>(limits::kMaxHistoryRows - 1));
    return {};
}

History sampleHistory(const Excitation1D& a, double mu, const std::vector<SlabEvent>& events,
                      double tauEnd, double step) {
    if (const std::string e = validateHistoryStep(tauEnd, step); !e.empty())
        throw std::invalid_argument(e);
    std::vector<double> times;
    const long n = static_cast<long>(std::floor(tauEnd / step));
    times.reserve(static_cast<std::size_t>(n) + 2 + events.size());
    for (long k = 0; k <= n; ++k)
        times.push_back(static_cast<double>(k) * step);
    for (const SlabEvent& e : events)
        times.push_back(e.tau);
    times.push_back(tauEnd);
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    History h;
    h.samples.reserve(times.size());
    for (double t : times)
        h.samples.push_back(stateAt(a, mu, events, t));
    return h;
}

std::string historyCsv(const History& h) {
    std::ostringstream s;
    s.imbue(std::locale::classic()); // a file: a decimal point whatever the user's locale
    s.precision(12);
    s << "tau,accel_g,delta,velocity,state\n";
    for (const auto& x : h.samples)
        s << x.tau << ',' << x.accel << ',' << x.delta << ',' << x.velocity << ',' << x.state
          << '\n';
    return s.str();
}

} // namespace kinstab
