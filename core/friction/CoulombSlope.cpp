// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/friction/CoulombSlope.h"

#include "core/base/TextInput.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace kinstab {

CoulombFit fitCoulombSlope(const std::vector<CoulombPoint>& all, double maxCpPsi,
                           std::optional<double> area) {
    if (area && !(*area > 0.0 && std::isfinite(*area)))
        throw std::invalid_argument("bearing area must be > 0 in^2, got " + formatDouble(*area));
    double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    for (const CoulombPoint& p : all) {
        if (p.cpPsi > maxCpPsi) continue;
        n += 1.0, sx += p.cpPsi, sy += p.vInfKips, sxx += p.cpPsi * p.cpPsi,
            sxy += p.cpPsi * p.vInfKips;
    }
    const double sxxCentred = sxx - sx * sx / std::max(n, 1.0);
    if (n < 2.0 || !(sxxCentred > 1e-12 * sxx))
        throw std::invalid_argument(
            "Coulomb slope: needs at least 2 distinct confining pressures <= " +
            formatDouble(maxCpPsi) + " psi");
    CoulombFit fit;
    fit.points = static_cast<int>(n);
    fit.slopeThroughOrigin = sxy / sxx;
    fit.slopeWithIntercept = (sxy - sx * sy / n) / sxxCentred;
    fit.interceptKips = (sy - fit.slopeWithIntercept * sx) / n;
    if (area) {
        // tau (psi) = 1000 V (kips) / A_b (in^2).
        fit.bearingAreaIn2 = area;
        fit.muThroughOrigin = 1000.0 * fit.slopeThroughOrigin / *area;
        fit.muWithIntercept = 1000.0 * fit.slopeWithIntercept / *area;
    }
    return fit;
}

} // namespace kinstab
