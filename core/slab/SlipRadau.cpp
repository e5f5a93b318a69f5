// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/slab/SlipRadau.h"

#include "core/numerics/RadauIIA.h"

#include <Eigen/LU>

#include <array>
#include <cmath>

namespace kinstab {

namespace {

using Mat2 = Eigen::Matrix2d;
using Vec2d = Eigen::Vector2d;

// The friction slip's acceleration at velocity u and its Jacobian -mu n / |u| (I - e e^T)
// = -rate p p^T (rate = mu n / |u|, p the unit normal to u: a rank-one matrix).
struct Slip {
    Vec2d f;
    double rate;
    Vec2d normal;
    Mat2 jac() const { return -rate * normal * normal.transpose(); }
};
Slip slipAt(const Vec2d& u, const Vec2d& a, double mun) {
    const double r = u.norm();
    const Vec2d e = u / r;
    return {-a - mun * e, mun / r, Vec2d(-e[1], e[0])};
}

double rmsNorm(const Eigen::Matrix<double, 6, 1>& v, const Vec2d& scale) {
    double s = 0.0;
    for (int i = 0; i < 6; ++i)
        s += (v[i] / scale[i % 2]) * (v[i] / scale[i % 2]);
    return std::sqrt(s / 6.0);
}

// RADAU5's estimate with the Jacobian at the step's start, J = [[0, I], [0, Ju]]:
// (u1/h I - J) x = c solves as x_u = (u1/h I - Ju)^-1 c_u, x_d = (c_d + x_u) h / u1. With
// `refine` (a first step or one after a rejection) a norm above 1 is re-estimated from
// f(t0, y0 + x), as RADAU5 does, since the first estimate can overrate stiff components.
double errorNorm(const SlabModel2D& m, double t0, const OdeVec<4>& y0, const OdeVec<4>& f0,
                 double h, const std::array<Vec2d, 3>& zd, const Eigen::Matrix<double, 6, 1>& z,
                 const OdeVec<4>& y1, const OdeVec<4>& absTol, double relTol, bool refine) {
    using namespace radau;
    const double mun = m.params().mu * m.normal(t0);
    const Vec2d u0(y0[2], y0[3]);
    const Vec2d e0 = u0 / u0.norm();
    const Vec2d a0 = -Vec2d(f0[2], f0[3]) - mun * e0;
    const Mat2 inverse = ((kU1 / h) * Mat2::Identity() - slipAt(u0, a0, mun).jac()).inverse();
    Vec2d hd = Vec2d::Zero(), hu = Vec2d::Zero();
    for (int i = 0; i < 3; ++i) {
        hd += kD[i] / h * zd[i];
        hu += kD[i] / h * z.segment<2>(2 * i);
    }
    auto norm = [&](const Vec2d& cd, const Vec2d& cu, Vec2d& xd, Vec2d& xu) {
        xu = inverse * cu;
        xd = (cd + xu) * h / kU1;
        double sum = 0.0;
        for (int i = 0; i < 4; ++i) {
            const double x = i < 2 ? xd[i] : xu[i - 2];
            const double sc =
                estimateScale(absTol[i], relTol, std::max(std::abs(y0[i]), std::abs(y1[i])));
            sum += (x / sc) * (x / sc);
        }
        return std::sqrt(sum / 4.0);
    };
    Vec2d xd, xu;
    double err = norm(Vec2d(f0[0], f0[1]) + hd, Vec2d(f0[2], f0[3]) + hu, xd, xu);
    if (err >= 1.0 && refine) {
        const Vec2d u = u0 + xu;
        if (!(u.norm() > 0.0)) return err;
        const Slip f = slipAt(u, a0, mun);
        err = norm(u + hd, f.f + hu, xd, xu);
    }
    return err;
}

// Newton's correction: solves (I - h A (x) J) dz = rhs, the stage Jacobians J_j = -c_j p_j p_j^T
// being of rank one (c_j = mu n_j / |u_j|, p_j the unit normal to u_j: Slip's rate, normal). The
// 6x6 matrix is then I + sum_j w_j q_j^T (q_j: p_j in block j; w_j: h A_ij c_j p_j in block i), and
// by the Sherman-Morrison-Woodbury identity dz = rhs - W M^-1 Q^T rhs with the 3x3 M = I + Q^T W,
// M_jk = h A_jk c_k p_j.p_k: the same solution as a 6x6 LU, at a fraction of its cost (that LU was
// a tenth of the planar solver's time).
Eigen::Matrix<double, 6, 1> newtonCorrection(const std::array<Slip, 3>& s, double h,
                                             const Eigen::Matrix<double, 6, 1>& rhs) {
    using namespace radau;
    Eigen::Matrix3d m;
    Eigen::Vector3d qb;
    for (int j = 0; j < 3; ++j) {
        qb[j] = s[j].normal.dot(rhs.segment<2>(2 * j));
        for (int k = 0; k < 3; ++k)
            m(j, k) =
                (j == k ? 1.0 : 0.0) + h * kA[j][k] * s[k].rate * s[j].normal.dot(s[k].normal);
    }
    const Eigen::Vector3d y = m.inverse() * qb; // cofactors: a 3x3 LU cost twice as much
    Eigen::Matrix<double, 6, 1> dz = rhs;
    for (int i = 0; i < 3; ++i)
        for (int k = 0; k < 3; ++k)
            dz.segment<2>(2 * i) -= h * kA[i][k] * s[k].rate * y[k] * s[k].normal;
    return dz;
}

} // namespace

Eigen::Vector2d SlipRadauPolynomial::at(double x) const {
    using namespace radau;
    const double nodes[4] = {0.0, kC[0], kC[1], kC[2]};
    const Eigen::Vector2d values[4] = {u0, u[0], u[1], u[2]};
    Eigen::Vector2d sum = Eigen::Vector2d::Zero();
    for (int i = 0; i < 4; ++i) {
        double w = 1.0;
        for (int j = 0; j < 4; ++j)
            if (j != i) w *= (x - nodes[j]) / (nodes[i] - nodes[j]);
        sum += w * values[i];
    }
    return sum;
}

SlipRadauStep slipRadauStep(const SlabModel2D& m, double t0, const OdeVec<4>& y0,
                            const OdeVec<4>& f0, double h, const OdeVec<4>& absTol, double relTol,
                            bool refine, const SlipRadauPolynomial* guess) {
    using namespace radau;
    SlipRadauStep r;
    const double mu = m.params().mu;
    const Vec2d u0(y0[2], y0[3]);
    std::array<Vec2d, 3> a;
    std::array<double, 3> mun;
    for (int i = 0; i < 3; ++i) {
        const double t = t0 + kC[i] * h;
        const Vec2 ai = m.accel(t);
        a[i] = Vec2d(ai.x, ai.y);
        mun[i] = mu * m.normal(t);
    }
    r.evaluations = 3;
    Eigen::Matrix<double, 6, 1> z;
    if (guess && guess->h > 0.0 && guess->t0 + guess->h == t0) {
        // Start from the previous step's collocation polynomial, extrapolated.
        for (int i = 0; i < 3; ++i)
            z.segment<2>(2 * i) = guess->at(1.0 + kC[i] * h / guess->h) - u0;
    } else {
        // Start: each stage slides along u0's direction under its own a_h and n.
        const Vec2d e0 = u0 / u0.norm();
        for (int i = 0; i < 3; ++i)
            z.segment<2>(2 * i) = kC[i] * h * (-a[i] - mun[i] * e0);
    }
    // Newton's corrections are measured against the error estimate's tolerances and stopped, as
    // in RADAU5, when the contraction rate says the rest is below fnewt of them.
    const double rtol = estimateRelTol(relTol);
    const Vec2d scale(estimateScale(absTol[2], relTol, std::abs(u0[0])),
                      estimateScale(absTol[3], relTol, std::abs(u0[1])));
    const double fnewt = std::max(10.0 * 2.2e-16 / rtol, std::min(0.03, std::sqrt(rtol)));
    std::array<Slip, 3> s;
    bool converged = false;
    double lastNorm = INFINITY;
    for (int k = 0; k < kSlipRadauMaxNewton && !converged; ++k) {
        Eigen::Matrix<double, 6, 1> g = z;
        for (int j = 0; j < 3; ++j) {
            const Vec2d uj = u0 + z.segment<2>(2 * j);
            // A stage at rest or turned against u0 holds a stop: not this step's business.
            if (!(uj.dot(u0) > 0.0)) return r;
            s[j] = slipAt(uj, a[j], mun[j]);
        }
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                g.segment<2>(2 * i) -= h * kA[i][j] * s[j].f;
        const Eigen::Matrix<double, 6, 1> dz = newtonCorrection(s, h, -g);
        z += dz;
        r.newton = k + 1;
        const double norm = rmsNorm(dz, scale);
        if (!std::isfinite(norm)) return r;
        if (k == 0) {
            converged = norm <= 1e-2 * fnewt;
        } else {
            const double theta = norm / lastNorm;
            if (theta >= 1.0 && k >= 2) return r; // diverges
            converged = theta < 1.0 && theta / (1.0 - theta) * norm <= fnewt;
        }
        lastNorm = norm;
    }
    if (!converged) return r;
    std::array<Vec2d, 3> u;
    for (int j = 0; j < 3; ++j)
        u[j] = u0 + z.segment<2>(2 * j);
    if (!(u[2].dot(u0) > 0.0)) return r;
    // Stiffly accurate: the end is the last stage; the displacement is the quadrature of u.
    std::array<Vec2d, 3> zd; // displacement stage increments
    for (int i = 0; i < 3; ++i) {
        zd[i] = Vec2d::Zero();
        for (int j = 0; j < 3; ++j)
            zd[i] += h * kA[i][j] * u[j];
    }
    const Vec2d dd = zd[2];
    const Slip end = slipAt(u[2], a[2], mun[2]);
    r.y << y0[0] + dd[0], y0[1] + dd[1], u[2][0], u[2][1];
    r.f << u[2][0], u[2][1], end.f[0], end.f[1];
    r.poly = {t0, h, u0, u};
    r.err = errorNorm(m, t0, y0, f0, h, zd, z, r.y, absTol, relTol, refine);
    return r;
}

} // namespace kinstab
