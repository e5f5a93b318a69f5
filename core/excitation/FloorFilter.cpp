// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/excitation/FloorFilter.h"

#include "core/base/TextInput.h"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace kinstab {

namespace {

// x_{i+1} = a11 x + a12 v + b11 g_i + b12 g_{i+1};  v_{i+1} = a21 x + a22 v + b21 g_i + b22 g_{i+1}
// (Nigam & Jennings 1969, eqs. for 0 <= zeta < 1 and a ground acceleration linear over dt).
struct Recurrence {
    double a11, a12, a21, a22, b11, b12, b21, b22;
};

Recurrence nigamJennings(double w, double zeta, double dt) {
    const double root = std::sqrt(1.0 - zeta * zeta);
    const double wd = w * root;
    const double e = std::exp(-zeta * w * dt);
    const double s = std::sin(wd * dt), c = std::cos(wd * dt);
    const double r = zeta / root;
    const double w2 = w * w, w3 = w2 * w;
    const double k1 = (2.0 * zeta * zeta - 1.0) / (w2 * dt);
    const double k2 = 2.0 * zeta / (w3 * dt);
    const double cs = c - r * s;             // cos - zeta/sqrt(1-zeta^2) sin
    const double ds = wd * s + zeta * w * c; // derivative factor
    Recurrence m{};
    m.a11 = e * (r * s + c);
    m.a12 = e * s / wd;
    m.a21 = -w / root * e * s;
    m.a22 = e * cs;
    m.b11 = e * ((k1 + zeta / w) * s / wd + (k2 + 1.0 / w2) * c) - k2;
    m.b12 = -e * (k1 * s / wd + k2 * c) - 1.0 / w2 + k2;
    m.b21 = e * ((k1 + zeta / w) * cs - (k2 + 1.0 / w2) * ds) + 1.0 / (w2 * dt);
    m.b22 = -e * (k1 * cs - k2 * ds) - 1.0 / (w2 * dt);
    return m;
}

} // namespace

InputProblem checkFloorFilter(const FloorFilterParams& p) {
    if (!(p.period >= kMinFloorPeriodS && p.period <= kMaxFloorPeriodS))
        return {"period_s", p.period, "s",
                "floor period " + formatDouble(p.period) + " s: must be at least " +
                    formatDouble(kMinFloorPeriodS) + " s and at most " +
                    formatDouble(kMaxFloorPeriodS) + " s"};
    if (!(p.damping >= 0.0) || !(p.damping < 1.0))
        return {"damping", p.damping, "",
                "damping " + formatDouble(p.damping) +
                    ": must be at least 0 and below 1 (fraction of critical)"};
    if (p.tail && (!(*p.tail >= 0.0) || !std::isfinite(*p.tail) || *p.tail > 1e5))
        return {"tail_s", *p.tail, "s",
                "tail " + formatDouble(*p.tail) + " s: must be between 0 and 1e5 s"};
    return {};
}

std::string validateFloorFilter(const FloorFilterParams& p) {
    return checkFloorFilter(p).why;
}

std::vector<double> floorAcceleration(const std::vector<double>& ground, double dt, double period,
                                      double damping, OscillatorState start) {
    const double w = 2.0 * std::numbers::pi / period;
    const Recurrence m = nigamJennings(w, damping, dt);
    std::vector<double> out(ground.size());
    double x = start.x, v = start.v;
    for (std::size_t i = 0; i < ground.size(); ++i) {
        if (i > 0) {
            const double g0 = ground[i - 1], g1 = ground[i];
            const double xn = m.a11 * x + m.a12 * v + m.b11 * g0 + m.b12 * g1;
            v = m.a21 * x + m.a22 * v + m.b21 * g0 + m.b22 * g1;
            x = xn;
        }
        out[i] = -(2.0 * damping * w * v + w * w * x);
    }
    return out;
}

double floorTailSeconds(const FloorFilterParams& p) {
    const double w = 2.0 * std::numbers::pi / p.period;
    return p.tail.value_or(p.damping > 0.0 ? std::min(std::log(100.0) / (p.damping * w), 120.0)
                                           : 0.0);
}

Accelerogram floorMotion(const Accelerogram& ground, const FloorFilterParams& p) {
    if (const std::string e = validateFloorFilter(p); !e.empty()) throw std::invalid_argument(e);
    validateAccelerogram(ground);
    const double tail = floorTailSeconds(p);
    std::vector<double> input = ground.samples;
    input.resize(input.size() + static_cast<std::size_t>(std::ceil(tail / ground.dt)), 0.0);
    Accelerogram floor = ground;
    floor.samples = floorAcceleration(input, ground.dt, p.period, p.damping);
    std::ostringstream name;
    name << "floor motion (T = " << p.period << " s, damping " << 100.0 * p.damping << " %) of "
         << (ground.name.empty() ? ground.sourceFile : ground.name);
    floor.name = name.str();
    floor.format = "floor filter";
    floor.headerPeak.reset();
    return floor;
}

} // namespace kinstab
