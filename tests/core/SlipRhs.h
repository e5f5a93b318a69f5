// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The planar slip's right-hand side written out from the model (core/slab/SlipRadau.h's
// equations, independent of the solver's own): the state (x, y, u_x, u_y); the friction opposes
// the sliding velocity u with magnitude μ n. Shared by tst_slip_radau and tst_step_kernels.

#include "core/numerics/Dopri5.h"
#include "core/slab/SlabModel2D.h"

#include <cmath>

namespace kinstab::testing {

inline OdeVec<4> slipRhs(const SlabModel2D& m, double t, const OdeVec<4>& y) {
    const Vec2 a = m.accel(t);
    const double mun = m.params().mu * m.normal(t), r = std::sqrt(y[2] * y[2] + y[3] * y[3]);
    OdeVec<4> f;
    f << y[2], y[3], -a.x - mun * y[2] / r, -a.y - mun * y[3] / r;
    return f;
}

} // namespace kinstab::testing
