// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One five-stage Radau IIA step (order 9; core/numerics/RadauIIA.h) of a planar slip,
//   u' = -a_h(tau) - mu n(tau) u / |u|,   delta' = u,   state (dx, dy, ux, uy).
// Why an implicit method: the friction term's Jacobian -mu n / |u| (I - e e^T) turns the
// direction of u towards its slow manifold at rate mu n / |u|. At the small speeds of grazing
// slips that rate caps an explicit method's step at a few |u| / (mu n) (stability, not
// accuracy); Radau IIA is L-stable, so its step is set by the tolerance alone.
// The time enters only through a_h and n, evaluated once per stage time; the Newton iteration
// on the five stage velocities (10 unknowns, exact Jacobian) costs no further evaluations.
// Why five stages: with three (order 5) the step was held by its order-3 error estimate to about
// 0.015 tau on slow slips (the period at 1 Hz is 10 tau), where the order-5 estimate of five
// stages allows steps about three times longer (docs/theory.md §6.5).

#include "core/numerics/Dop853.h"
#include "core/numerics/RadauIIA.h"
#include "core/slab/SlabModel2D.h"

#include <array>

namespace kinstab {

// The step's collocation polynomial of u through u0 and the stage velocities: a dense output
// and the next step's starting guess (extrapolated).
struct SlipRadauPolynomial {
    SlipRadauPolynomial() = default;
    // Through u0 at t0 and u[i] at t0 + c_i h.
    SlipRadauPolynomial(double t0, double h, const Eigen::Vector2d& u0,
                        const std::array<Eigen::Vector2d, radau::kStages>& u);
    Eigen::Vector2d at(double x) const; // u at t0 + x h
    // The displacement from t0 to t0 + x h: h times the integral of the polynomial (the dense
    // output of the collocation method, error O(h^6)).
    Eigen::Vector2d displacement(double x) const;

    double t0 = 0, h = 0;                                           // h = 0: none
    std::array<Eigen::Vector2d, radau::kStages + 1> coefficients{}; // of x^0 ... x^s
};

struct SlipRadauStep {
    OdeVec<4> y;           // at t0 + h
    OdeVec<4> f;           // derivative there
    double err = INFINITY; // RADAU5 error norm (<= 1: accepted); infinite when Newton failed
    int newton = 0;        // iterations used
    long evaluations = 0;  // of a_h and n
    SlipRadauPolynomial poly;
};

inline constexpr int kSlipRadauMaxNewton = 8;

// f0 = the slip's derivative at (t0, y0); |u0| > 0. absTol, relTol as for the explicit step.
// refine: the first step of a slip or one after a rejection (see the error estimate). guess:
// the previous step's polynomial, used when that step ended at t0.
SlipRadauStep slipRadauStep(const SlabModel2D& m, double t0, const OdeVec<4>& y0,
                            const OdeVec<4>& f0, double h, const OdeVec<4>& absTol, double relTol,
                            bool refine, const SlipRadauPolynomial* guess = nullptr);
// The same with the estimate's tolerances formed once by the caller (a run: the cube root per
// step was a hundredth of the planar solver's instructions).
SlipRadauStep slipRadauStep(const SlabModel2D& m, double t0, const OdeVec<4>& y0,
                            const OdeVec<4>& f0, double h, const OdeVec<4>& absTol,
                            const radau::EstimateTolerance& tol, bool refine,
                            const SlipRadauPolynomial* guess = nullptr);

} // namespace kinstab
