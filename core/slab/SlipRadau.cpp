// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/slab/SlipRadau.h"

#include "core/numerics/RadauIIA.h"
#include "core/numerics/SmallLinearSolve.h"

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

constexpr int kS = radau::kStages;
using Stages = Eigen::Matrix<double, 2 * kS, 1>; // the stage velocity increments, two per stage
using StageMatrix = std::array<std::array<double, kS>, kS>;

double rmsNorm(const Stages& v, const Vec2d& scale) {
    double s = 0.0;
    for (int i = 0; i < 2 * kS; ++i)
        s += (v[i] / scale[i % 2]) * (v[i] / scale[i % 2]);
    return std::sqrt(s / (2.0 * kS));
}

// RADAU5's estimate with the Jacobian at the step's start, J = [[0, I], [0, Ju]]:
// (u1/h I - J) x = c solves as x_u = (u1/h I - Ju)^-1 c_u, x_d = (c_d + x_u) h / u1. With
// `refine` (a first step or one after a rejection) a norm above 1 is re-estimated from
// f(t0, y0 + x), as RADAU5 does, since the first estimate can overrate stiff components.
double errorNorm(const SlabModel2D& m, double t0, const OdeVec<4>& y0, const OdeVec<4>& f0,
                 double h, const std::array<Vec2d, kS>& zd, const Stages& z, const OdeVec<4>& y1,
                 const OdeVec<4>& absTol, const radau::EstimateTolerance& tol, bool refine) {
    using namespace radau;
    const double mun = m.params().mu * m.normal(t0);
    const Vec2d u0(y0[2], y0[3]);
    const Vec2d e0 = u0 / u0.norm();
    const Vec2d a0 = -Vec2d(f0[2], f0[3]) - mun * e0;
    const Mat2 inverse = ((kU1 / h) * Mat2::Identity() - slipAt(u0, a0, mun).jac()).inverse();
    Vec2d hd = Vec2d::Zero(), hu = Vec2d::Zero();
    for (int i = 0; i < kS; ++i) {
        hd += kD[i] / h * zd[i];
        hu += kD[i] / h * z.segment<2>(2 * i);
    }
    auto norm = [&](const Vec2d& cd, const Vec2d& cu, Vec2d& xd, Vec2d& xu) {
        xu = inverse * cu;
        xd = (cd + xu) * h / kU1;
        double sum = 0.0;
        for (int i = 0; i < 4; ++i) {
            const double x = i < 2 ? xd[i] : xu[i - 2];
            const double sc = tol.scale(absTol[i], std::max(std::abs(y0[i]), std::abs(y1[i])));
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

// Newton's matrix I - h A (x) J, the stage Jacobians J_j = -c_j p_j p_j^T being of rank one
// (c_j = mu n_j / |u_j|, p_j the unit normal to u_j: Slip's rate, normal). The 10x10 matrix is
// then I + sum_j w_j q_j^T (q_j: p_j in block j; w_j: h A_ij c_j p_j in block i), and by the
// Sherman-Morrison-Woodbury identity its solution is dz = rhs - W M^-1 Q^T rhs with the 5x5
// M = I + Q^T W, M_jk = delta_jk + h A_jk c_k p_j.p_k: the same solution as a 10x10 LU, at a
// fraction of its cost (with three stages the 6x6 LU had been a tenth of the planar solver's
// time). M is factored by core/numerics/SmallLinearSolve.h. hA = h A, formed once per step.
struct NewtonMatrix {
    std::array<Vec2d, kS> normal;
    StageMatrix hAc; // h A_ik c_k
    SmallLu<kS> lu;
    bool ok = false; // M regular
};
// Formed in place: returning and copying the struct had cost a third as much as forming it.
// The loops run over contiguous rows (rates, h A's rows, M's rows), which the compiler pairs.
void formNewtonMatrix(NewtonMatrix& n, const std::array<Slip, kS>& s, const StageMatrix& hA) {
    std::array<std::array<double, kS>, kS> dot; // symmetric: formed once per pair
    std::array<double, kS> rate;
    for (int j = 0; j < kS; ++j) {
        n.normal[j] = s[j].normal;
        rate[j] = s[j].rate;
        for (int k = j; k < kS; ++k)
            dot[j][k] = dot[k][j] = s[j].normal.dot(s[k].normal);
    }
    SmallLu<kS>::Rows m;
    for (int j = 0; j < kS; ++j) {
        for (int k = 0; k < kS; ++k)
            n.hAc[j][k] = hA[j][k] * rate[k];
        for (int k = 0; k < kS; ++k)
            m[j][k] = (j == k ? 1.0 : 0.0) + n.hAc[j][k] * dot[j][k];
    }
    n.ok = n.lu.factor(m);
}

// Newton's correction dz = rhs - W M^-1 Q^T rhs (NaN when M is singular: Newton then stops, no
// finite norm). Each block's terms are subtracted in the order of k.
Stages newtonCorrection(const NewtonMatrix& n, const Stages& rhs) {
    Eigen::Matrix<double, kS, 1> y;
    for (int j = 0; j < kS; ++j)
        y[j] = n.normal[j].dot(rhs.segment<2>(2 * j));
    if (n.ok)
        n.lu.solve(y);
    else
        y.setConstant(NAN);
    Stages dz = rhs;
    for (int i = 0; i < kS; ++i) {
        std::array<double, kS> w;
        for (int k = 0; k < kS; ++k)
            w[k] = n.hAc[i][k] * y[k];
        Vec2d d = dz.segment<2>(2 * i);
        for (int k = 0; k < kS; ++k)
            d -= w[k] * n.normal[k];
        dz.segment<2>(2 * i) = d;
    }
    return dz;
}

double node(int i) { // the polynomial's nodes: 0, c_1, ..., c_s
    return i == 0 ? 0.0 : radau::kC[i - 1];
}

} // namespace

// The monomial coefficients from the values at the nodes: the inverse of the nodes' Vandermonde
// matrix, formed once. Evaluating Lagrange's form at each stage of each step had cost a twelfth
// of the planar solver's time.
SlipRadauPolynomial::SlipRadauPolynomial(double start, double length, const Eigen::Vector2d& u0,
                                         const std::array<Eigen::Vector2d, radau::kStages>& u)
    : t0(start), h(length) {
    using Nodes = Eigen::Matrix<double, kS + 1, kS + 1>;
    static const Nodes kInverseVandermonde = [] {
        Nodes v;
        for (int i = 0; i <= kS; ++i)
            for (int m = 0; m <= kS; ++m)
                v(i, m) = std::pow(node(i), m);
        return Nodes(v.inverse());
    }();
    for (int m = 0; m <= kS; ++m) {
        Eigen::Vector2d c = kInverseVandermonde(m, 0) * u0;
        for (int i = 1; i <= kS; ++i)
            c += kInverseVandermonde(m, i) * u[static_cast<std::size_t>(i - 1)];
        coefficients[static_cast<std::size_t>(m)] = c;
    }
}

Eigen::Vector2d SlipRadauPolynomial::at(double x) const {
    Eigen::Vector2d sum = coefficients[kS];
    for (int m = kS - 1; m >= 0; --m)
        sum = sum * x + coefficients[static_cast<std::size_t>(m)];
    return sum;
}

Eigen::Vector2d SlipRadauPolynomial::displacement(double x) const {
    Eigen::Vector2d sum = coefficients[kS] / (kS + 1.0);
    for (int m = kS - 1; m >= 0; --m)
        sum = sum * x + coefficients[static_cast<std::size_t>(m)] / (m + 1.0);
    return h * x * sum;
}

SlipRadauStep slipRadauStep(const SlabModel2D& m, double t0, const OdeVec<4>& y0,
                            const OdeVec<4>& f0, double h, const OdeVec<4>& absTol, double relTol,
                            bool refine, const SlipRadauPolynomial* guess) {
    return slipRadauStep(m, t0, y0, f0, h, absTol, radau::EstimateTolerance(relTol), refine, guess);
}

namespace {

// The stage times' a_h and mu n: the only evaluations of the step.
struct StageForcing {
    std::array<Vec2d, kS> a;
    std::array<double, kS> mun;
};
StageForcing stageForcing(const SlabModel2D& m, double t0, double h) {
    StageForcing f;
    const double mu = m.params().mu;
    for (int i = 0; i < kS; ++i) {
        const double t = t0 + radau::kC[i] * h;
        const Vec2 ai = m.accel(t);
        f.a[i] = Vec2d(ai.x, ai.y);
        f.mun[i] = mu * m.normal(t);
    }
    return f;
}

// Newton's starting stages.
Stages startingStages(const Vec2d& u0, double t0, double h, const StageForcing& f,
                      const SlipRadauPolynomial* guess) {
    using namespace radau;
    Stages z;
    if (guess && guess->h > 0.0 && guess->t0 + guess->h == t0 && h <= kMaxGrowth * guess->h) {
        // Start from the previous step's collocation polynomial, extrapolated: no further than
        // the step control lets a step grow. A step cut short at a window's end can be
        // a few ulps long, and the degree-5 polynomial extrapolated 1e12 times its length gave a
        // start from which Newton converged to another root of the collocation equations (an
        // error of 4e-5 in u that the estimate, built on the same stages, accepted).
        for (int i = 0; i < kS; ++i)
            z.segment<2>(2 * i) = guess->at(1.0 + kC[i] * h / guess->h) - u0;
    } else {
        // Start: each stage slides along u0's direction under its own a_h and n.
        const Vec2d e0 = u0 / u0.norm();
        for (int i = 0; i < kS; ++i)
            z.segment<2>(2 * i) = kC[i] * h * (-f.a[i] - f.mun[i] * e0);
    }
    return z;
}

// The first correction's norm (in units of the estimate's tolerances) above which the second
// iteration forms Newton's matrix anew. Measured on the 33x33 bench grid: the first norms
// cluster at 1e2..1e3; 10 forms it in nearly every step, 1e3 keeps Newton's failures and
// iterations as with the full Newton method, and always keeping it cost 1 % more instructions
// with RSN68 UP (Newton failed 4x as often).
constexpr double kRefactorNorm = 1e3;

// Newton's iteration on the stages z (in place); false when it fails (a stage at rest or turned
// against u0, no finite norm, divergence, or no convergence in kSlipRadauMaxNewton). Newton's
// corrections are measured against the error estimate's tolerances and stopped, as in RADAU5,
// when the contraction rate says the rest is below fnewt of them.
bool newtonSolve(Stages& z, const Vec2d& u0, const StageForcing& f, const StageMatrix& hA,
                 const Vec2d& scale, double fnewt, int& iterations) {
    std::array<Slip, kS> s;
    NewtonMatrix matrix;
    double lastNorm = INFINITY;
    for (int k = 0; k < kSlipRadauMaxNewton; ++k) {
        Stages g = z;
        for (int j = 0; j < kS; ++j) {
            const Vec2d uj = u0 + z.segment<2>(2 * j);
            // A stage at rest or turned against u0 holds a stop: not this step's business.
            if (!(uj.dot(u0) > 0.0)) return false;
            s[j] = slipAt(uj, f.a[j], f.mun[j]);
        }
        for (int i = 0; i < kS; ++i)
            for (int j = 0; j < kS; ++j)
                g.segment<2>(2 * i) -= hA[i][j] * s[j].f;
        // Simplified Newton after a small first correction (RADAU5 keeps its matrix while it
        // converges): the Jacobian at the first iterate converges the rest as well. After a
        // large one (a poor start: with a vertical record, a window's first step after the
        // sample's kink) the matrix is formed anew, or Newton fails 4x as often.
        if (k == 0 || lastNorm > kRefactorNorm) formNewtonMatrix(matrix, s, hA);
        const Stages dz = newtonCorrection(matrix, -g);
        z += dz;
        iterations = k + 1;
        const double norm = rmsNorm(dz, scale);
        if (!std::isfinite(norm)) return false;
        const double theta = norm / lastNorm;
        if (k > 0 && theta >= 1.0 && k >= 2) return false; // diverges
        const bool converged =
            k == 0 ? norm <= 1e-2 * fnewt : theta < 1.0 && theta / (1.0 - theta) * norm <= fnewt;
        if (converged) return true;
        lastNorm = norm;
    }
    return false;
}

} // namespace

SlipRadauStep slipRadauStep(const SlabModel2D& m, double t0, const OdeVec<4>& y0,
                            const OdeVec<4>& f0, double h, const OdeVec<4>& absTol,
                            const radau::EstimateTolerance& tol, bool refine,
                            const SlipRadauPolynomial* guess) {
    SlipRadauStep r;
    const Vec2d u0(y0[2], y0[3]);
    const StageForcing f = stageForcing(m, t0, h);
    r.evaluations = kS;
    Stages z = startingStages(u0, t0, h, f, guess);
    const Vec2d scale(tol.scale(absTol[2], std::abs(u0[0])), tol.scale(absTol[3], std::abs(u0[1])));
    const double fnewt = std::max(10.0 * 2.2e-16 / tol.rtol, std::min(0.03, std::sqrt(tol.rtol)));
    StageMatrix hA;
    for (int i = 0; i < kS; ++i)
        for (int j = 0; j < kS; ++j)
            hA[i][j] = h * radau::kA[i][j];
    if (!newtonSolve(z, u0, f, hA, scale, fnewt, r.newton)) return r;
    std::array<Vec2d, kS> u;
    for (int j = 0; j < kS; ++j)
        u[j] = u0 + z.segment<2>(2 * j);
    if (!(u[kS - 1].dot(u0) > 0.0)) return r;
    // Stiffly accurate: the end is the last stage; the displacement is the quadrature of u.
    std::array<Vec2d, kS> zd; // displacement stage increments
    for (int i = 0; i < kS; ++i) {
        zd[i] = Vec2d::Zero();
        for (int j = 0; j < kS; ++j)
            zd[i] += hA[i][j] * u[j];
    }
    const Vec2d dd = zd[kS - 1];
    const Vec2d& u1 = u[kS - 1];
    const Slip end = slipAt(u1, f.a[kS - 1], f.mun[kS - 1]);
    r.y << y0[0] + dd[0], y0[1] + dd[1], u1[0], u1[1];
    r.f << u1[0], u1[1], end.f[0], end.f[1];
    r.poly = SlipRadauPolynomial(t0, h, u0, u);
    r.err = errorNorm(m, t0, y0, f0, h, zd, z, r.y, absTol, tol, refine);
    return r;
}

} // namespace kinstab
