// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One step of the Dormand-Prince 8(5,3) pair, DOP853 (Hairer, Norsett & Wanner, Solving ODEs I,
// 2nd ed., sec. II.10, code DOP853), with its combined 5th/3rd-order error estimate. Order 8: on
// the smooth enveloped sines of the planar slab it takes steps several times longer than
// Dormand-Prince 5(4) at the same tolerance, for twice the evaluations per step.
// Coefficients as in Hairer's dop853.f (also in SciPy's dop853_coefficients.py).

#include "core/numerics/Dopri5.h"

#include "core/numerics/PredictiveStep.h"

#include <algorithm>
#include <cmath>

namespace kinstab {

namespace dop853 {
// Row 12 of kA holds the weights b of the 8th-order solution.
inline constexpr double kC[12] = {0.0,
                                  0.05260015195876773,
                                  0.0789002279381516,
                                  0.1183503419072274,
                                  0.2816496580927726,
                                  0.3333333333333333,
                                  0.25,
                                  0.3076923076923077,
                                  0.6512820512820513,
                                  0.6,
                                  0.8571428571428571,
                                  1.0};
inline constexpr double kA[13][12] = {
    {0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
    {0.05260015195876773, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
    {0.0197250569845379, 0.0591751709536137, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
    {0.02958758547680685, 0.0, 0.08876275643042054, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0},
    {0.2413651341592667, 0.0, -0.8845494793282861, 0.924834003261792, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0,
     0.0, 0.0},
    {0.037037037037037035, 0.0, 0.0, 0.17082860872947386, 0.12546768756682242, 0.0, 0.0, 0.0, 0.0,
     0.0, 0.0, 0.0},
    {0.037109375, 0.0, 0.0, 0.17025221101954405, 0.06021653898045596, -0.017578125, 0.0, 0.0, 0.0,
     0.0, 0.0, 0.0},
    {0.03709200011850479, 0.0, 0.0, 0.17038392571223998, 0.10726203044637328, -0.015319437748624402,
     0.008273789163814023, 0.0, 0.0, 0.0, 0.0, 0.0},
    {0.6241109587160757, 0.0, 0.0, -3.3608926294469414, -0.868219346841726, 27.59209969944671,
     20.154067550477894, -43.48988418106996, 0.0, 0.0, 0.0, 0.0},
    {0.47766253643826434, 0.0, 0.0, -2.4881146199716677, -0.590290826836843, 21.230051448181193,
     15.279233632882423, -33.28821096898486, -0.020331201708508627, 0.0, 0.0, 0.0},
    {-0.9371424300859873, 0.0, 0.0, 5.186372428844064, 1.0914373489967295, -8.149787010746927,
     -18.52006565999696, 22.739487099350505, 2.4936055526796523, -3.0467644718982196, 0.0, 0.0},
    {2.273310147516538, 0.0, 0.0, -10.53449546673725, -2.0008720582248625, -17.9589318631188,
     27.94888452941996, -2.8589982771350235, -8.87285693353063, 12.360567175794303,
     0.6433927460157636, 0.0},
    {0.054293734116568765, 0.0, 0.0, 0.0, 0.0, 4.450312892752409, 1.8915178993145003,
     -5.801203960010585, 0.3111643669578199, -0.1521609496625161, 0.20136540080403034,
     0.04471061572777259},
};
inline constexpr double kE3[13] = {-0.18980075407240762,
                                   0.0,
                                   0.0,
                                   0.0,
                                   0.0,
                                   4.450312892752409,
                                   1.8915178993145003,
                                   -5.801203960010585,
                                   -0.4226823213237919,
                                   -0.1521609496625161,
                                   0.20136540080403034,
                                   0.02265179219836082,
                                   0.0};
inline constexpr double kE5[13] = {0.01312004499419488,
                                   0.0,
                                   0.0,
                                   0.0,
                                   0.0,
                                   -1.2251564463762044,
                                   -0.4957589496572502,
                                   1.6643771824549864,
                                   -0.35032884874997366,
                                   0.3341791187130175,
                                   0.08192320648511571,
                                   -0.022355307863886294,
                                   0.0};
} // namespace dop853

template <int N> struct Dop853Result {
    OdeVec<N> y;          // 8th-order solution at t + h
    OdeVec<N> f;          // derivative there (first stage of the next step: FSAL)
    OdeVec<N> err5, err3; // the two embedded error estimates (times h)
};

// rhs(t, y) -> dy/dt. f0 = rhs(t, y0). 12 evaluations. Where rhs reads only the components
// [First, First + Count) of y (the planar slab's reads the velocity, not the displacement, which
// is a quadrature), only those of the stage states are formed and the others are y0's: half the
// stage arithmetic of a planar slip's step, with the same bits in every result.
template <int N, int First = 0, int Count = N, class Rhs>
Dop853Result<N> dop853Step(Rhs&& rhs, double t, const OdeVec<N>& y0, const OdeVec<N>& f0,
                           double h) {
    using namespace dop853;
    static_assert(First >= 0 && Count > 0 && First + Count <= N);
    using Read = Eigen::Matrix<double, Count, 1>;
    OdeVec<N> k[12];
    k[0] = f0;
    OdeVec<N> stage = y0;
    for (int s = 1; s < 12; ++s) {
        Read acc = kA[s][0] * k[0].template segment<Count>(First);
        for (int j = 1; j < s; ++j)
            if (kA[s][j] != 0.0) acc += kA[s][j] * k[j].template segment<Count>(First);
        stage.template segment<Count>(First) = y0.template segment<Count>(First) + h * acc;
        k[s] = rhs(t + kC[s] * h, stage);
    }
    Dop853Result<N> r;
    OdeVec<N> b = OdeVec<N>::Zero(), e5 = OdeVec<N>::Zero(), e3 = OdeVec<N>::Zero();
    for (int j = 0; j < 12; ++j) {
        b += kA[12][j] * k[j];
        e5 += kE5[j] * k[j];
        e3 += kE3[j] * k[j];
    }
    r.y = y0 + h * b;
    r.f = rhs(t + h, r.y);
    r.err5 = h * e5;
    r.err3 = h * e3;
    return r;
}

// Hairer's error norm of DOP853: <= 1 means the step meets the tolerances.
template <int N>
double dop853ErrorNorm(const Dop853Result<N>& r, const OdeVec<N>& y0, const OdeVec<N>& absTol,
                       double relTol) {
    double s5 = 0.0, s3 = 0.0;
    for (int i = 0; i < N; ++i) {
        const double sc = absTol[i] + relTol * std::max(std::abs(y0[i]), std::abs(r.y[i]));
        const double q5 = r.err5[i] / sc, q3 = r.err3[i] / sc;
        s5 += q5 * q5;
        s3 += q3 * q3;
    }
    if (s5 == 0.0 && s3 == 0.0) return 0.0;
    return s5 / std::sqrt((s5 + 0.01 * s3) * N);
}

// The factor by which to scale h after a step with error norm err (order 8: exponent 1/8,
// safety 0.9, limited to [0.2, 10]).
inline double dop853StepFactor(double err) {
    if (!(err > 0.0)) return 10.0;
    // err^(-1/8) by three square roots: pow took 4% of the planar solver's time.
    return std::clamp(0.9 / std::sqrt(std::sqrt(std::sqrt(err))), 0.2, 10.0);
}

// Gustafsson's predictive control (core/numerics/PredictiveStep.h) with DOP853's exponent 1/8,
// limited as dop853StepFactor.
inline double dop853PredictiveFactor(double h, double err, double hPrev, double errPrev) {
    const double trend = std::sqrt(std::sqrt(std::sqrt(err * err / errPrev)));
    return std::clamp(predictiveStepFactor(h, hPrev, trend), 0.2, 10.0);
}

// The step to retry with after a step rejected with error norm err (NaN: a fifth of it).
inline double dop853RetryStep(double h, double err) {
    return h * (std::isfinite(err) ? dop853StepFactor(err) : 0.2);
}

} // namespace kinstab
