// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One step of the Dormand-Prince 5(4) pair (Dormand & Prince 1980; Hairer, Norsett & Wanner,
// Solving ODEs I, Table II.5.2), with its embedded error estimate and a cubic Hermite continuous
// extension. Step-size control and events are the caller's: the planar slab needs its own
// (tstops at onset roots, a change of independent variable near a stop; docs/theory.md §6.5).

#include <Eigen/Core>

#include <algorithm>
#include <cmath>

namespace kinstab {

template <int N> using OdeVec = Eigen::Matrix<double, N, 1>;

template <int N> struct Dopri5Result {
    OdeVec<N> y;     // 5th-order solution at t + h
    OdeVec<N> f;     // derivative there (first stage of the next step: FSAL)
    OdeVec<N> error; // y5 - y4, the local error estimate
};

// rhs(t, y) -> dy/dt. f0 = rhs(t, y0).
template <int N, class Rhs>
Dopri5Result<N> dopri5Step(Rhs&& rhs, double t, const OdeVec<N>& y0, const OdeVec<N>& f0,
                           double h) {
    constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
    constexpr double a21 = 1.0 / 5;
    constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
    constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
    constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561,
                     a54 = -212.0 / 729;
    constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                     a65 = -5103.0 / 18656;
    constexpr double b1 = 35.0 / 384, b3 = 500.0 / 1113, b4 = 125.0 / 192, b5 = -2187.0 / 6784,
                     b6 = 11.0 / 84;
    constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920,
                     e5 = -17253.0 / 339200, e6 = 22.0 / 525, e7 = -1.0 / 40;
    const OdeVec<N> k1 = f0;
    const OdeVec<N> k2 = rhs(t + c2 * h, OdeVec<N>(y0 + h * a21 * k1));
    const OdeVec<N> k3 = rhs(t + c3 * h, OdeVec<N>(y0 + h * (a31 * k1 + a32 * k2)));
    const OdeVec<N> k4 = rhs(t + c4 * h, OdeVec<N>(y0 + h * (a41 * k1 + a42 * k2 + a43 * k3)));
    const OdeVec<N> k5 =
        rhs(t + c5 * h, OdeVec<N>(y0 + h * (a51 * k1 + a52 * k2 + a53 * k3 + a54 * k4)));
    const OdeVec<N> k6 =
        rhs(t + h, OdeVec<N>(y0 + h * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5)));
    Dopri5Result<N> r;
    r.y = y0 + h * (b1 * k1 + b3 * k3 + b4 * k4 + b5 * k5 + b6 * k6);
    r.f = rhs(t + h, r.y);
    r.error = h * (e1 * k1 + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6 + e7 * r.f);
    return r;
}

// Scaled RMS norm of the error (Hairer's err): <= 1 means the step meets the tolerances.
// absTol per component lets a component be measured in its own units.
template <int N>
double dopri5ErrorNorm(const OdeVec<N>& error, const OdeVec<N>& y0, const OdeVec<N>& y1,
                       const OdeVec<N>& absTol, double relTol) {
    double sum = 0.0;
    for (int i = 0; i < N; ++i) {
        const double sc = absTol[i] + relTol * std::max(std::abs(y0[i]), std::abs(y1[i]));
        const double q = error[i] / sc;
        sum += q * q;
    }
    return std::sqrt(sum / N);
}

// The factor by which to scale h after a step with error norm err (order 5, safety 0.9,
// growth limited to [0.2, 5]).
inline double dopri5StepFactor(double err) {
    if (!(err > 0.0)) return 5.0;
    return std::clamp(0.9 * std::pow(err, -0.2), 0.2, 5.0);
}

// Cubic Hermite interpolant on [t0, t0 + h] from values and derivatives at both ends.
template <int N>
OdeVec<N> hermiteCubic(const OdeVec<N>& y0, const OdeVec<N>& f0, const OdeVec<N>& y1,
                       const OdeVec<N>& f1, double h, double theta) {
    const double t2 = theta * theta, t3 = t2 * theta;
    const double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + theta, h01 = -2 * t3 + 3 * t2,
                 h11 = t3 - t2;
    return h00 * y0 + h10 * h * f0 + h01 * y1 + h11 * h * f1;
}

} // namespace kinstab
