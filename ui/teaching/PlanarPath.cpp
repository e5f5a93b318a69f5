// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/teaching/PlanarPath.h"

#include <algorithm>

namespace kinstab::ui {

HistorySample planarStateAt(const std::vector<PlanarSample>& path, double tau, bool alongWalls) {
    HistorySample s;
    s.tau = tau;
    if (path.empty() || tau < path.front().tau) return s;
    const auto pos = [&](const PlanarSample& p) { return alongWalls ? p.dy : p.dx; };
    const auto vel = [&](const PlanarSample& p) { return alongWalls ? p.uy : p.ux; };
    const auto it = std::upper_bound(path.begin(), path.end(), tau,
                                     [](double t, const PlanarSample& p) { return t < p.tau; });
    if (it == path.end()) {
        s.delta = pos(path.back());
        return s;
    }
    const PlanarSample& a = *std::prev(it);
    const PlanarSample& b = *it;
    const double h = b.tau - a.tau;
    if (!(h > 0.0)) {
        s.delta = pos(a);
        return s;
    }
    // Cubic Hermite on [a, b] with u = (tau - a) / h.
    const double u = (tau - a.tau) / h, u2 = u * u, u3 = u2 * u;
    const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2,
                 h11 = u3 - u2;
    s.delta = h00 * pos(a) + h10 * h * vel(a) + h01 * pos(b) + h11 * h * vel(b);
    const double d00 = 6 * u2 - 6 * u, d10 = 3 * u2 - 4 * u + 1, d01 = -6 * u2 + 6 * u,
                 d11 = 3 * u2 - 2 * u;
    s.velocity = (d00 * pos(a) + d01 * pos(b)) / h + d10 * vel(a) + d11 * vel(b);
    const bool slipping = a.slipping && (b.slipping || u < 1.0);
    s.state = slipping ? (s.velocity > 0) - (s.velocity < 0) : 0;
    return s;
}

} // namespace kinstab::ui
