// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/slab/RegularizedSolver.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace kinstab {

namespace {

struct State {
    double x = 0, v = 0;
};

// Stability: RK4's real-axis limit is 2.785; width / mu keeps h mu / width = 1.
double automaticStep(const SlabParams& p, const RegularizedSettings& s) {
    if (s.step > 0.0) return s.step;
    double h = p.mu > 0.0 ? s.width / p.mu : std::numeric_limits<double>::infinity();
    if (s.period > 0.0) h = std::min(h, s.period / 32.0);
    if (!std::isfinite(h)) h = 1e-2;
    return h;
}

// One classical RK4 step of length hh from (tau, y).
template <class Rhs> State rk4Step(Rhs& rhs, double tau, const State& y, double hh) {
    const State k1 = rhs(tau, y);
    const State k2 = rhs(tau + 0.5 * hh, {y.x + 0.5 * hh * k1.x, y.v + 0.5 * hh * k1.v});
    const State k3 = rhs(tau + 0.5 * hh, {y.x + 0.5 * hh * k2.x, y.v + 0.5 * hh * k2.v});
    const State k4 = rhs(tau + hh, {y.x + hh * k3.x, y.v + hh * k3.v});
    return {y.x + hh / 6.0 * (k1.x + 2.0 * k2.x + 2.0 * k3.x + k4.x),
            y.v + hh / 6.0 * (k1.v + 2.0 * k2.v + 2.0 * k3.v + k4.v)};
}

// The step from y to next (length hh from tau) crossed the limit: the collapse time by linear
// interpolation of delta within the step, and the state there.
void collapseInStep(SlabResult& r, double limit, double& tau, State& y, const State& next,
                    double hh) {
    const double target = std::copysign(limit, next.x);
    const double frac = (target - y.x) / (next.x - y.x);
    r.tauC = tau + std::clamp(frac, 0.0, 1.0) * hh;
    r.outcome = Outcome::Collapsed;
    tau = r.tauC;
    y = {target, next.v};
}

} // namespace

std::string validateRegularizedSettings(const RegularizedSettings& s) {
    std::ostringstream m;
    if (!std::isfinite(s.width) || s.width <= 0.0)
        m << "width = " << s.width << ": must be a positive number";
    else if (!std::isfinite(s.step) || s.step < 0.0)
        m << "step = " << s.step << ": must be >= 0 (0: automatic)";
    else if (!std::isfinite(s.endTau) || s.endTau < 0.0)
        m << "endTau = " << s.endTau << ": must be >= 0";
    return m.str();
}

SlabResult solveRegularized(const Excitation1D& a, const SlabParams& p,
                            const RegularizedSettings& s) {
    SlabResult r;
    if (const std::string e = validateRegularizedSettings(s); !e.empty()) {
        r.failure = e;
        return r;
    }
    const double h = automaticStep(p, s);
    const double end = s.endTau > 0.0 ? s.endTau : p.duration.value_or(0.0);
    auto rhs = [&](double tau, const State& y) {
        ++r.work.accelEvaluations;
        return State{y.v, -p.mu * std::tanh(y.v / s.width) - a.accel(tau)};
    };
    State y;
    double tau = 0.0;
    for (long n = 0;; ++n) {
        const bool pastEnd = end > 0.0 ? tau >= end : a.boundAfter(tau) < p.mu;
        if (pastEnd) {
            r.outcome = Outcome::Stable;
            break;
        }
        if (n >= s.maxSteps) {
            r.outcome = Outcome::Failed;
            r.failure = "step limit reached";
            break;
        }
        const double hh = end > 0.0 ? std::min(h, end - tau) : h;
        const State next = rk4Step(rhs, tau, y, hh);
        ++r.work.steps;
        if (!std::isfinite(next.x) || !std::isfinite(next.v)) {
            r.outcome = Outcome::Failed;
            r.failure = "non-finite state (step too large for the width?)";
            break;
        }
        if (std::abs(next.x) > p.limit) {
            collapseInStep(r, p.limit, tau, y, next, hh);
            break;
        }
        // tau from the step count, not by accumulation (docs/theory.md §6.6 case 13).
        tau = hh < h ? tau + hh : static_cast<double>(n + 1) * h;
        y = next;
        r.maxAbsDelta = std::max(r.maxAbsDelta, std::abs(y.x));
    }
    r.maxAbsDelta = std::max(r.maxAbsDelta, std::abs(y.x));
    r.tauEnd = tau;
    r.residualDelta = y.x;
    return r;
}

} // namespace kinstab
