// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// An independent solution of the 1-DOF slab equations for the tests (docs/theory.md §4), sharing
// nothing with the exact solver but the excitation's a(tau): it marches in fixed small steps,
// integrates v and delta by 10-point Gauss-Legendre quadrature of a(tau) (no closed forms), detects
// events by sign changes sampled at several points per step (no log-concavity brackets) and refines
// each by plain bisection to ~1e-15.

#include "core/excitation/Excitation1D.h"
#include "core/numerics/GaussLegendre.h"
#include "core/slab/SlabTypes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace kinstab::testing {

struct ReferenceResult {
    Outcome outcome = Outcome::Failed;
    double tauC = std::numeric_limits<double>::quiet_NaN();
    int slipIntervals = 0;
    double residualDelta = 0;
};

class QuadratureReference {
public:
    QuadratureReference(const Excitation1D& a, double mu, double limit, double step)
        : a_(a), mu_(mu), limit_(limit), h_(step) {}

    ReferenceResult run(double tauMax) {
        ReferenceResult r;
        double t = 0, x = 0, v = 0;
        int s = 0;
        while (t < tauMax) {
            if (s == 0 && a_.boundAfter(t) < mu_) {
                r.outcome = Outcome::Stable;
                r.residualDelta = x;
                return r;
            }
            const double t1 = t + h_;
            if (s == 0) {
                // Onset: first sampled point in the step with |a| > mu, then bisect back.
                double prev = t, found = -1;
                for (int k = 1; k <= kSamples; ++k) {
                    const double tk = t + h_ * k / kSamples;
                    if (std::abs(a_.accel(tk)) > mu_) {
                        found =
                            bisect([&](double u) { return std::abs(a_.accel(u)) - mu_; }, prev, tk);
                        break;
                    }
                    prev = tk;
                }
                if (found < 0) {
                    t = t1;
                    continue;
                }
                t = found;
                s = a_.accel(std::min(t + 1e-12, t1)) > 0 ? -1 : 1;
                ++r.slipIntervals;
            }
            // Slip from t to the end of the step (or an event inside it).
            const double t0 = t, x0 = x, v0 = v;
            const int s0 = s;
            auto vel = [&](double u) { return v0 - s0 * mu_ * (u - t0) - integralA(t0, u); };
            auto disp = [&](double u) {
                const double d = u - t0;
                return x0 + v0 * d - 0.5 * s0 * mu_ * d * d - momentA(t0, u);
            };
            double tEnd = t1;
            bool stop = false;
            double prev = t0;
            for (int k = 1; k <= kSamples; ++k) {
                const double tk = t0 + (t1 - t0) * k / kSamples;
                if (s0 * vel(tk) <= 0.0) {
                    tEnd = bisect([&](double u) { return s0 * vel(u); }, prev, tk);
                    stop = true;
                    break;
                }
                prev = tk;
            }
            const double xEnd = disp(tEnd);
            if (std::abs(xEnd) > limit_) {
                r.tauC = bisect([&](double u) { return std::abs(disp(u)) - limit_; }, t0, tEnd);
                r.outcome = Outcome::Collapsed;
                r.residualDelta = disp(r.tauC);
                return r;
            }
            t = tEnd;
            x = xEnd;
            v = stop ? 0.0 : vel(tEnd);
            if (stop) {
                if (std::abs(a_.accel(t)) > mu_) {
                    s = -s0;
                    ++r.slipIntervals;
                } else {
                    s = 0;
                }
            }
        }
        r.outcome = Outcome::Failed;
        return r;
    }

private:
    static constexpr int kSamples = 8;

    // f(lo) and f(hi) of opposite sign (or f(hi) == 0); returns the sign-change point.
    template <class F> static double bisect(F&& f, double lo, double hi) {
        double flo = f(lo);
        for (int i = 0; i < 200 && hi - lo > 1e-15 * std::max(1.0, std::abs(hi)); ++i) {
            const double mid = 0.5 * (lo + hi);
            const double fm = f(mid);
            if ((fm > 0.0) == (flo > 0.0) && fm != 0.0) {
                lo = mid;
                flo = fm;
            } else {
                hi = mid;
            }
        }
        return hi;
    }
    // Composite Gauss-Legendre over sub-steps no longer than h_.
    template <class G> double gauss(double t0, double t1, G&& g) const {
        const int pieces = std::max(1, static_cast<int>(std::ceil((t1 - t0) / h_)));
        double sum = 0;
        for (int p = 0; p < pieces; ++p) {
            const double lo = t0 + (t1 - t0) * p / pieces, hi = t0 + (t1 - t0) * (p + 1) / pieces;
            sum += gaussLegendre10(g, lo, hi);
        }
        return sum;
    }
    double integralA(double t0, double t1) const {
        return gauss(t0, t1, [&](double u) { return a_.accel(u); });
    }
    // int_{t0}^{t1} (t1 - u) a(u) du = the double integral of a.
    double momentA(double t0, double t1) const {
        return gauss(t0, t1, [&](double u) { return (t1 - u) * a_.accel(u); });
    }

    const Excitation1D& a_;
    double mu_, limit_, h_;
};

} // namespace kinstab::testing
