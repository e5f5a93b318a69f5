// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/slab/PlanarSolver.h"

#include "core/numerics/GaussLegendre.h"
#include "core/numerics/VectorState.h"

#include "core/numerics/Dop853.h"
#include "core/numerics/LevelCrossings.h"
#include "core/numerics/RootFinding.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace kinstab {

namespace {

using Vec4 = OdeVec<4>; // (dx, dy, ux, uy) in tau
using Vec5 = OdeVec<5>; // (ex, ey, tau - tau_entry, dx, dy) in s = ln|u|

// Below this speed a slip is slaved to -a_h (see PlanarRun::slaved).
constexpr double kSlaved = 1e-6;

// 10-point Gauss-Legendre on [-1, 1] (the quadrature of a slip's first stretch).
class PlanarRun {
public:
    PlanarRun(const SlabModel2D& m, const PlanarOptions& o) : m_(m), o_(o), mu_(m.params().mu) {}
    PlanarResult run();

private:
    enum class Step { Continue, Done };
    enum class Approach { Stopped, Exited, ReachedEnd, Done };

    Vec4 rhs(double tau, const Vec4& y);
    Vec5 rhsS(double s, const Vec5& z);
    double dissipationRate(double tau, double ex, double ey); // D = mu n + a.e = -d|u|/dtau

    Step window(double w0, double w1);
    Step slipTo(double end);
    Step slaved(double end);
    bool isSlaved(double tau, const Vec4& y) const;
    Approach approachStop(double end);
    Step afterStop();
    double locate(auto&& fdf, double lo, double hi, double flo, double fhi);
    bool collapseIn(const Vec4& yEnd, int& comp, double& sign) const;
    Step collapse(double tau, const Vec4& y, int comp);

    void moveTo(double tau, const Vec4& y);
    bool event(EventKind kind);
    Step finish(Outcome o);
    Step fail(const std::string& why) {
        r_.slab.failure = why;
        return finish(Outcome::Failed);
    }

    const SlabModel2D& m_;
    const PlanarOptions& o_;
    double mu_;
    PlanarResult r_;
    double t_ = 0;
    Vec4 y_ = Vec4::Zero();
    bool slipping_ = false;
    double hNext_ = 0;       // step proposal in tau
    double slipPeak_ = 0;    // largest |u| of the current slip (scale of the stop floor)
    double startLength_ = 0; // length of a slip's quadrature start
    double fsalT_ = -1.0;    // the last accepted step's end, state and derivative
    Vec4 fsalY_ = Vec4::Zero(), fsalF_ = Vec4::Zero();
};

Vec4 PlanarRun::rhs(double tau, const Vec4& y) {
    ++r_.slab.work.accelEvaluations;
    const Vec2 a = m_.accel(tau);
    const double n = m_.normal(tau);
    const double rho = std::hypot(y[2], y[3]);
    double ex = 0, ey = 0;
    if (rho > 0.0) {
        ex = y[2] / rho;
        ey = y[3] / rho;
    } else if (const double am = std::hypot(a.x, a.y); am > 0.0) {
        ex = -a.x / am; // at rest the slab starts along -a_h
        ey = -a.y / am;
    }
    Vec4 f;
    f << y[2], y[3], -mu_ * n * ex - a.x, -mu_ * n * ey - a.y;
    return f;
}

double PlanarRun::dissipationRate(double tau, double ex, double ey) {
    const Vec2 a = m_.accel(tau);
    return mu_ * m_.normal(tau) + a.x * ex + a.y * ey;
}

// Log-radius form (docs/theory.md §6.5): with u = e^s (cos th, sin th), D = mu n + a.e,
//   dth/ds = (a.e_perp)/D,  dtau/ds = -e^s/D,  d delta/ds = e^s e dtau/ds.
// Smooth as s -> -inf wherever D > 0 (where |u| decreases).
Vec5 PlanarRun::rhsS(double s, const Vec5& z) {
    ++r_.slab.work.accelEvaluations;
    const double tau = z[2] + t_;
    const double norm = std::hypot(z[0], z[1]);
    const double ex = z[0] / norm, ey = z[1] / norm;
    const Vec2 a = m_.accel(tau);
    const double d = mu_ * m_.normal(tau) + a.x * ex + a.y * ey;
    const double turn = (-a.x * ey + a.y * ex) / d;
    const double rho = std::exp(s);
    const double dtau = -rho / d;
    Vec5 f;
    f << -turn * ey, turn * ex, dtau, rho * ex * dtau, rho * ey * dtau;
    return f;
}

void PlanarRun::moveTo(double tau, const Vec4& y) {
    t_ = tau;
    y_ = y;
    r_.slab.maxAbsDelta = std::max(r_.slab.maxAbsDelta, std::abs(y[0]));
    r_.maxAbsDeltaY = std::max(r_.maxAbsDeltaY, std::abs(y[1]));
    slipPeak_ = std::max(slipPeak_, std::hypot(y[2], y[3]));
    if (o_.recordPath) r_.path.push_back({tau, y[0], y[1], y[2], y[3], slipping_});
}

bool PlanarRun::event(EventKind kind) {
    ++r_.slab.work.events;
    if (o_.recordEvents) r_.events.push_back({t_, kind, y_[0], y_[1], y_[2], y_[3]});
    if (r_.slab.work.events > o_.maxEvents) {
        fail("more than " + std::to_string(o_.maxEvents) + " events (chattering guard)");
        return false;
    }
    return true;
}

PlanarRun::Step PlanarRun::finish(Outcome o) {
    r_.slab.outcome = o;
    r_.slab.tauEnd = t_;
    r_.slab.residualDelta = y_[0];
    r_.residualDeltaY = y_[1];
    return Step::Done;
}

double PlanarRun::locate(auto&& fdf, double lo, double hi, double flo, double fhi) {
    const RootResult root = safeguardedNewton(fdf, lo, hi, flo, fhi);
    r_.slab.work.rootIterations += root.iterations;
    return std::clamp(root.x, std::min(lo, hi), std::max(lo, hi));
}

PlanarResult PlanarRun::run() {
    const PlanarParams& p = m_.params();
    const double end = p.duration.value_or(std::numeric_limits<double>::infinity());
    if (!p.duration && !m_.quietAfter(std::numeric_limits<double>::max())) {
        fail("the excitation never decays below mu n: set a duration (tau_out)");
        return r_;
    }
    // Quadrature start of a slip: short against the horizontal time scale, so that the
    // neglected lag of the direction behind -a_h (relative size (omega h)^2) stays below the
    // tolerances (docs/theory.md §6.1 F7: the direction is slaved at rate |a|/|u|).
    startLength_ = m_.horizontalTimeScale() / 250.0;
    if (m_.normal(0.0) <= 0.0) {
        r_.tauLiftOff = 0.0;
        r_.slab.tauC = 0.0;
        event(EventKind::LiftOff);
        finish(Outcome::LiftOff);
        return r_;
    }
    double w0 = 0.0;
    while (true) {
        if (!slipping_ && m_.quietAfter(w0)) {
            t_ = std::max(t_, w0);
            event(EventKind::Stable);
            finish(Outcome::Stable);
            return r_;
        }
        if (w0 >= end) {
            event(EventKind::DurationCap);
            finish(Outcome::Stable);
            return r_;
        }
        double w1 = std::min(m_.segmentEnd(w0), end);
        if (!(w1 > w0)) w1 = std::nextafter(w0, end);
        if (window(w0, w1) == Step::Done) return r_;
        w0 = w1;
    }
}

// One window of the time line: find lift-off and the onset roots in it, then walk the pieces
// between them; on each piece the sign of |a_h| - mu n is fixed.
PlanarRun::Step PlanarRun::window(double w0, double w1) {
    constexpr int kSub = 8;
    CrossingScanWork scan;
    double wEnd = w1;
    bool lifts = false;
    if (m_.mayLiftOn(w0, w1)) {
        std::vector<double> roots;
        levelCrossings(
            [&](double t, double& f, double& df) {
                f = -m_.normal(t);
                df = -m_.normalSlope(t);
            },
            w0, w1, kSub, roots, scan);
        if (!roots.empty()) {
            wEnd = roots.front();
            lifts = true;
        }
    }
    std::vector<double> cuts{w0};
    if (!m_.quietOn(w0, wEnd))
        levelCrossings(
            [&](double t, double& f, double& df) {
                f = m_.onsetMargin(t);
                df = m_.onsetMarginSlope(t);
            },
            w0, wEnd, kSub, cuts, scan);
    cuts.push_back(wEnd);
    r_.slab.work.accelEvaluations += scan.evaluations;
    r_.slab.work.rootIterations += scan.iterations;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
        const double lo = std::max(cuts[i], t_), hi = cuts[i + 1];
        if (!(hi > lo)) continue;
        const bool excess = m_.onsetMargin(0.5 * (lo + hi)) > 0.0;
        while (t_ < hi || !slipping_) {
            if (!slipping_) {
                if (!excess) break;
                // Slip onset: the slab lags the walls and starts along -a_h.
                t_ = std::max(t_, lo);
                slipping_ = true;
                slipPeak_ = 0.0;
                y_[2] = y_[3] = 0.0;
                ++r_.slab.slipIntervals;
                if (!event(EventKind::SlipOnset)) return Step::Done;
            }
            if (slipTo(hi) == Step::Done) return Step::Done;
            if (t_ >= hi) break;
        }
        if (!slipping_) t_ = std::max(t_, hi);
    }
    if (lifts) {
        // n reached 0: the slab leaves its support. Reported, never integrated through.
        t_ = wEnd;
        r_.tauLiftOff = wEnd;
        r_.slab.tauC = wEnd;
        event(EventKind::LiftOff);
        return finish(Outcome::LiftOff);
    }
    return Step::Continue;
}

// Slides from t_ to end, or until the slab sticks (then returns with slipping_ false).
PlanarRun::Step PlanarRun::slipTo(double end) {
    const PlanarParams& p = m_.params();
    Vec4 absTol = Vec4::Constant(o_.absTol);
    while (t_ < end) {
        const double rho = std::hypot(y_[2], y_[3]);
        if (isSlaved(t_, y_)) {
            const Step s = slaved(end);
            if (s == Step::Done || !slipping_) return s;
            continue;
        }
        // The derivative at the state an accepted step ended on is that step's last stage (FSAL).
        const Vec4 f0 = t_ == fsalT_ && y_ == fsalY_ ? fsalF_ : rhs(t_, y_);
        const double d = -(y_[2] * f0[2] + y_[3] * f0[3]) / rho; // -d|u|/dtau
        double h = std::min(hNext_ > 0.0 ? hNext_ : rho / (mu_ + 1.0), end - t_);
        if (d > 0.0 && rho <= d * h) {
            // A stop is predicted within the step: go on in s = ln|u|.
            switch (approachStop(end)) {
            case Approach::Done:
                return Step::Done;
            case Approach::ReachedEnd:
                return Step::Continue;
            case Approach::Exited:
                continue;
            case Approach::Stopped:
                if (afterStop() == Step::Done) return Step::Done;
                if (!slipping_) return Step::Continue;
                continue;
            }
        }
        if (++r_.slab.work.steps > o_.maxSteps) return fail("step limit reached");
        const auto st =
            dop853Step<4>([&](double t, const Vec4& y) { return rhs(t, y); }, t_, y_, f0, h);
        const double err = dop853ErrorNorm<4>(st, y_, absTol, o_.relTol);
        if (!(err <= 1.0)) {
            ++r_.slab.work.restarts;
            hNext_ = h * std::max(0.2, std::isfinite(err) ? dop853StepFactor(err) : 0.2);
            if (hNext_ < 1e-15 * std::max(1.0, t_)) return fail("step size underflow in a slip");
            continue;
        }
        int comp = -1;
        double sign = 0;
        if (collapseIn(st.y, comp, sign)) {
            const double lim = comp == 0 ? p.limit : p.theta;
            const Vec4 y0 = y_;
            const double t0 = t_;
            const double tc = locate(
                [&](double t, double& f, double& df) {
                    const auto s = dop853Step<4>(
                        [&](double tt, const Vec4& yy) { return rhs(tt, yy); }, t0, y0, f0, t - t0);
                    f = sign * s.y[comp] - lim;
                    df = sign * s.y[comp + 2];
                },
                t0, t0 + h, sign * y0[comp] - lim, sign * st.y[comp] - lim);
            const auto sc = dop853Step<4>([&](double tt, const Vec4& yy) { return rhs(tt, yy); },
                                          t0, y0, f0, tc - t0);
            return collapse(tc, sc.y, comp);
        }
        if (st.y[2] * y_[2] + st.y[3] * y_[3] < 0.0) {
            // The velocity turned over within one step: it passed a stop; retake it shorter so
            // the stop is approached in s.
            ++r_.slab.work.restarts;
            hNext_ = 0.5 * h;
            continue;
        }
        const bool truncated = h < hNext_;
        moveTo(t_ + h, st.y);
        fsalT_ = t_;
        fsalY_ = y_;
        fsalF_ = st.f;
        const double grow = h * dop853StepFactor(err);
        hNext_ = truncated ? std::max(hNext_, grow) : grow;
    }
    return Step::Continue;
}

bool PlanarRun::collapseIn(const Vec4& y, int& comp, double& sign) const {
    const PlanarParams& p = m_.params();
    if (std::abs(y[0]) > p.limit) {
        comp = 0;
        sign = y[0] > 0.0 ? 1.0 : -1.0;
        return true;
    }
    if (std::abs(y[1]) > p.theta) {
        comp = 1;
        sign = y[1] > 0.0 ? 1.0 : -1.0;
        return true;
    }
    return false;
}

PlanarRun::Step PlanarRun::collapse(double tau, const Vec4& y, int comp) {
    moveTo(tau, y);
    r_.slab.tauC = tau;
    r_.exitSide = comp == 0 ? ExitSide::Across : ExitSide::Along;
    if (!event(EventKind::Collapse)) return Step::Done;
    return finish(Outcome::Collapsed);
}

// Slaved slip: while |u| is tiny the direction of u relaxes to -a_h at rate |a|/|u| and lags it
// by only Omega |u| / |a| (docs/theory.md §6.1 F7), so |u| is the quadrature of |a_h| - mu n and
// the displacement its integral along -a_h: a slip's first stretch from u = 0, and grazing slips
// and stops, where an explicit method would crawl at steps of |u| / |a|. The neglected lag changes
// |u| by O(Omega^2 |u|^2 / |a|) per unit time: below 1e-12 for |u| <= kSlaved.
PlanarRun::Step PlanarRun::slaved(double end) {
    auto margin = [&](double s) {
        ++r_.slab.work.accelEvaluations;
        return m_.onsetMargin(s);
    };
    auto unitA = [&](double s) {
        const Vec2 a = m_.accel(s);
        const double am = std::hypot(a.x, a.y);
        return am > 0.0 ? Vec2{a.x / am, a.y / am} : Vec2{0.0, 0.0};
    };
    double rho = std::hypot(y_[2], y_[3]);
    while (t_ < end) {
        const double t0 = t_, h = std::min(startLength_, end - t0), r0 = rho;
        ++r_.slab.work.steps;
        auto speedAt = [&](double t) { return r0 + gaussLegendre10(margin, t0, t); };
        // The displacement along -a_h over [t0, t1], both components from one quadrature.
        auto shift = [&](double t1) {
            const double m = 0.5 * (t0 + t1), r = 0.5 * (t1 - t0);
            Vec2 sum;
            for (std::size_t i = 0; i < kGaussLegendre10Nodes.size(); ++i)
                for (double node :
                     {m - r * kGaussLegendre10Nodes[i], m + r * kGaussLegendre10Nodes[i]}) {
                    const Vec2 e = unitA(node);
                    const double v = kGaussLegendre10Weights[i] * speedAt(node);
                    sum.x += v * e.x;
                    sum.y += v * e.y;
                }
            return Vec2{r * sum.x, r * sum.y};
        };
        const double rEnd = speedAt(t0 + h);
        Vec4 y = y_;
        if (!(rEnd > 0.0)) {
            // The speed reaches zero in this stretch (it is monotone: the sign of |a_h| - mu n
            // is fixed on a piece): a stop.
            const double ts = r0 <= 0.0 ? t0
                                        : locate(
                                              [&](double t, double& f, double& df) {
                                                  f = speedAt(t);
                                                  df = margin(t);
                                              },
                                              t0, t0 + h, r0, rEnd);
            const Vec2 d = shift(ts);
            y[0] -= d.x;
            y[1] -= d.y;
            y[2] = y[3] = 0.0;
            moveTo(ts, y);
            return afterStop();
        }
        const Vec2 d = shift(t0 + h);
        y[0] -= d.x;
        y[1] -= d.y;
        rho = rEnd;
        // Direction at the end: -a_h, lagging its turn (rate Omega) by Omega |u| / |a|.
        const double tEnd = t0 + h;
        const Vec2 a = m_.accel(tEnd), sl = m_.accelSlope(tEnd);
        const double am2 = a.x * a.x + a.y * a.y;
        const Vec2 ah = unitA(tEnd);
        const double lag =
            am2 > 0.0 ? -(a.x * sl.y - a.y * sl.x) / am2 * rho / std::sqrt(am2) : 0.0;
        const double c = std::cos(lag), sn = std::sin(lag);
        y[2] = -rho * (ah.x * c - ah.y * sn);
        y[3] = -rho * (ah.x * sn + ah.y * c);
        // The direction relaxes at rate |a|/|u|: the first explicit step must resolve that.
        hNext_ = 0.5 * rho / std::max(std::sqrt(am2), 1e-300);
        moveTo(tEnd, y);
        if (rho > 10.0 * kSlaved) break;
    }
    return Step::Continue;
}

// True when |u| is small enough and u points along -a_h, so that the slip is slaved.
bool PlanarRun::isSlaved(double tau, const Vec4& y) const {
    const double rho = std::hypot(y[2], y[3]);
    if (rho > kSlaved) return false;
    if (rho == 0.0) return true;
    const Vec2 a = m_.accel(tau);
    const double am = std::hypot(a.x, a.y);
    return am > 0.0 && -(a.x * y[2] + a.y * y[3]) / (am * rho) >= 1.0 - 1e-6;
}

// Approach of a stop in s = ln|u|, from the current state (|u| > 0, |u| decreasing).
PlanarRun::Approach PlanarRun::approachStop(double end) {
    const PlanarParams& p = m_.params();
    const double tEntry = t_;
    double rho = std::hypot(y_[2], y_[3]);
    double s = std::log(rho);
    const double sFloor = std::log(1e-14 * std::max(slipPeak_, rho));
    Vec5 z;
    z << y_[2] / rho, y_[3] / rho, 0.0, y_[0], y_[1];
    auto f = [&](double ss, const Vec5& zz) { return rhsS(ss, zz); };
    Vec5 fz = f(s, z);
    Vec5 absTol;
    absTol << o_.relTol, o_.relTol, o_.relTol, o_.absTol, o_.absTol;
    double ds = -1.0;
    auto toTau = [&](const Vec5& zz, double ss) {
        Vec4 y;
        const double r = std::exp(ss), nrm = std::hypot(zz[0], zz[1]);
        y << zz[3], zz[4], r * zz[0] / nrm, r * zz[1] / nrm;
        return y;
    };
    while (true) {
        if (s <= sFloor) {
            // Stopped: the rest of the way is |u| / D at slope -D (F7 (c)).
            const double tau = tEntry + z[2];
            const double d = dissipationRate(tau, z[0], z[1]);
            Vec4 y = toTau(z, s);
            y[2] = y[3] = 0.0;
            moveTo(tau + std::exp(s) / std::max(d, 1e-300), y);
            return Approach::Stopped;
        }
        const double h = std::max(ds, sFloor - s);
        if (++r_.slab.work.steps > o_.maxSteps) {
            fail("step limit reached");
            return Approach::Done;
        }
        const auto st = dop853Step<5>(f, s, z, fz, h);
        const double err = dop853ErrorNorm<5>(st, z, absTol, o_.relTol);
        const double tauNew = tEntry + st.y[2];
        const double dNew = dissipationRate(tauNew, st.y[0] / std::hypot(st.y[0], st.y[1]),
                                            st.y[1] / std::hypot(st.y[0], st.y[1]));
        if (!(err <= 1.0) || !(dNew > 0.0) || !(st.y[2] >= z[2])) {
            ++r_.slab.work.restarts;
            ds = h * 0.25;
            if (std::abs(ds) < 1e-12) {
                // |u| turns before reaching 0: back to time as the variable.
                moveTo(tEntry + z[2], toTau(z, s));
                hNext_ = 0.1 * std::exp(s) / (mu_ * m_.normal(t_) + 1e-300);
                return Approach::Exited;
            }
            continue;
        }
        auto reStep = [&](double sTarget) { return dop853Step<5>(f, s, z, fz, sTarget - s).y; };
        if (tauNew > end) {
            // The piece ends before the stop: find s with tau(s) = end and go back to time.
            const double sEnd = locate(
                [&](double ss, double& g, double& dg) {
                    const Vec5 zz = reStep(ss);
                    g = tEntry + zz[2] - end;
                    dg = f(ss, zz)[2];
                },
                s + h, s, tauNew - end, tEntry + z[2] - end);
            const Vec5 zz = reStep(sEnd);
            moveTo(end, toTau(zz, sEnd));
            hNext_ = 0.1 * std::exp(sEnd) / (mu_ * m_.normal(end) + 1e-300);
            return Approach::ReachedEnd;
        }
        const Vec4 yNew = toTau(st.y, s + h);
        int comp = -1;
        double sign = 0;
        if (collapseIn(yNew, comp, sign)) {
            const double lim = comp == 0 ? p.limit : p.theta;
            const int k = comp + 3;
            const double sc = locate(
                [&](double ss, double& g, double& dg) {
                    const Vec5 zz = reStep(ss);
                    g = sign * zz[k] - lim;
                    dg = sign * f(ss, zz)[k];
                },
                s + h, s, sign * st.y[k] - lim, sign * z[k] - lim);
            const Vec5 zz = reStep(sc);
            collapse(tEntry + zz[2], toTau(zz, sc), comp);
            return Approach::Done;
        }
        s += h;
        z = st.y;
        const double nrm = std::hypot(z[0], z[1]);
        z[0] /= nrm;
        z[1] /= nrm;
        fz = f(s, z);
        ds = h * dop853StepFactor(err);
        if (isSlaved(tauNew, toTau(z, s))) {
            moveTo(tauNew, toTau(z, s));
            return Approach::Exited;
        }
        // The speed is about to turn (D -> 0): leave s before dtau/ds blows up.
        const Vec2 a = m_.accel(tauNew);
        if (dNew < 1e-3 * (mu_ * m_.normal(tauNew) + std::hypot(a.x, a.y))) {
            moveTo(tauNew, toTau(z, s));
            hNext_ = 0.1 * std::exp(s) / (mu_ * m_.normal(t_) + std::hypot(a.x, a.y) + 1e-300);
            return Approach::Exited;
        }
    }
}

// At a stop: stick if |a_h| <= mu n, else slide on at once along -a_h (a reversal).
PlanarRun::Step PlanarRun::afterStop() {
    y_[2] = y_[3] = 0.0;
    if (m_.onsetMargin(t_) > 0.0) {
        ++r_.slab.slipIntervals;
        slipPeak_ = 0.0;
        return event(EventKind::Reversal) ? Step::Continue : Step::Done;
    }
    slipping_ = false;
    return event(EventKind::Stick) ? Step::Continue : Step::Done;
}

} // namespace

PlanarResult solvePlanar(const SlabModel2D& model, const PlanarOptions& options) {
    clearUpperVectorState(); // see VectorState.h: a host process may leave AVX state dirty
    const std::string e = validatePlanarParams(model.params());
    if (!e.empty()) {
        PlanarResult r;
        r.slab.outcome = Outcome::Failed;
        r.slab.failure = e;
        return r;
    }
    return PlanarRun(model, options).run();
}

} // namespace kinstab
