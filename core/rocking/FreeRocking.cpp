// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/rocking/FreeRocking.h"

#include <algorithm>
#include <cmath>

namespace kinstab {

double housnerQuarterPeriod(double p, double tiltRatio) {
    return std::acosh(1.0 / (1.0 - tiltRatio)) / p;
}

namespace {
double potential(RockingEquations eq, double p, double alpha, double z, double theta) {
    const double d = alpha * z - theta;
    return eq == RockingEquations::Exact ? p * p * std::cos(d) : -0.5 * p * p * d * d;
}
double sideOf(double theta, double omega) {
    if (theta != 0.0) return theta > 0.0 ? 1.0 : -1.0;
    return omega < 0.0 ? -1.0 : 1.0;
}
} // namespace

double rockingEnergy(RockingEquations eq, double p, double alpha, double theta, double omega) {
    return 0.5 * omega * omega + potential(eq, p, alpha, sideOf(theta, omega), theta);
}

double balanceEnergy(RockingEquations eq, double p) {
    return eq == RockingEquations::Exact ? p * p : 0.0;
}

double freeAmplitude(RockingEquations eq, double p, double alpha, double energy) {
    if (eq == RockingEquations::Exact)
        return alpha - std::acos(std::clamp(energy / (p * p), -1.0, 1.0));
    return alpha - std::sqrt(std::max(0.0, -2.0 * energy)) / p;
}

// Energy decides: outside the corner's vertical (z theta >= alpha) gravity drives the block
// outwards, inside it back to theta = 0, where an impact multiplies theta'^2 by eta^2 and the
// block goes on about the other corner. At most two impacts are ahead before the answer is
// known (inwards from outside, then once more from inside).
FreeFate freeFate(RockingEquations eq, double p, double alpha, double eta, double theta,
                  double omega) {
    FreeFate fate;
    fate.maxAbsTheta = std::abs(theta);
    const double top = balanceEnergy(eq, p);
    for (int pass = 0; pass < 4; ++pass) {
        const double z = sideOf(theta, omega);
        const double e = 0.5 * omega * omega + potential(eq, p, alpha, z, theta);
        const bool outwards = z * omega > 0.0;
        if (z * theta >= alpha) {
            if (outwards || !(e > top)) return {true, fate.maxAbsTheta};
        } else if (outwards) {
            if (e > top) return {true, fate.maxAbsTheta};
            fate.maxAbsTheta = std::max(fate.maxAbsTheta, freeAmplitude(eq, p, alpha, e));
            return fate;
        } else if (omega == 0.0 && theta == 0.0) {
            return fate; // at rest on its base
        }
        // Inwards to theta = 0, the impact, and outwards about the other corner.
        const double v0 = std::sqrt(std::max(0.0, 2.0 * (e - potential(eq, p, alpha, z, 0.0))));
        theta = 0.0;
        omega = -z * eta * v0; // the rotation keeps its sense: towards -z
        if (omega == 0.0) return fate;
    }
    return fate;
}

double linearAmplitudeAfterImpacts(double tiltRatio, double eta, int n) {
    const double q = 1.0 - tiltRatio;
    const double e2n = std::pow(eta, 2.0 * n);
    return 1.0 - std::sqrt(1.0 - e2n * (1.0 - q * q));
}

} // namespace kinstab
