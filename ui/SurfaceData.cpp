// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/SurfaceData.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace kinstab::ui {

GammaGrid gammaGrid(const SweepResult& r, double tauRef) {
    GammaGrid g;
    g.amplitudes = r.grid.amplitudes;
    g.frequencies = r.grid.frequencies;
    const std::vector<double> gamma = collapseFactors(r, tauRef);
    g.gamma.resize(gamma.size());
    for (std::size_t k = 0; k < gamma.size(); ++k)
        g.gamma[k] =
            k < r.done.size() && r.done[k] ? gamma[k] : std::numeric_limits<double>::quiet_NaN();
    return g;
}

double gammaAtAmplitude(const GammaGrid& g, std::size_t fi, double a) {
    const auto& as = g.amplitudes;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    if (as.empty() || a < as.front() || a > as.back()) return nan;
    const auto it = std::lower_bound(as.begin(), as.end(), a);
    const auto i1 = static_cast<std::size_t>(it - as.begin());
    if (i1 == 0 || as[i1] == a) return g.at(i1, fi);
    const std::size_t i0 = i1 - 1;
    const double t = (a - as[i0]) / (as[i1] - as[i0]);
    return (1 - t) * g.at(i0, fi) + t * g.at(i1, fi);
}

std::size_t nearestFrequency(const GammaGrid& g, double f) {
    std::size_t best = 0;
    for (std::size_t j = 1; j < g.frequencies.size(); ++j)
        if (std::abs(g.frequencies[j] - f) < std::abs(g.frequencies[best] - f)) best = j;
    return best;
}

} // namespace kinstab::ui
