// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/slab/PlanarSolver.h"

#include "core/numerics/VectorState.h"

#include "core/numerics/Dop853.h"
#include "core/numerics/LevelCrossings.h"
#include "core/numerics/RadauIIA.h"
#include "core/numerics/RootFinding.h"
#include "core/slab/SlipRadau.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

namespace kinstab {

namespace {

using Vec4 = OdeVec<4>; // (dx, dy, ux, uy) in tau
using Vec5 = OdeVec<5>; // (ex, ey, tau - tau_entry, dx, dy) in s = ln|u|
using Vec3 = OdeVec<3>; // (|u|, dx, dy) in tau, on the slow manifold

// Sub-intervals of a window scanned for onset and lift-off roots (each holds at most one extremum
// of |a_h| - mu n: a window is at most a half-period of each component or one record sample).
constexpr int kOnsetSub = 8;

// Where a velocity component changes sign inside a step of length h from y0 to y1, the
// extremum of the cubic Hermite interpolant of that displacement (error O(h^4)): its value,
// and where it lies as a fraction of the step.
struct Extremum {
    double value = 0.0;
    double fraction = 0.0;
};
using StepExtrema = std::array<std::optional<Extremum>, 2>; // dx, dy; none: keeps its sign

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
    void addScanWork(const CrossingScanWork& scan);
    void scanCuts();
    double nextOnset(double from);
    double nextCut(double tau);
    Step slipTo(double end);
    struct Trial {
        Vec4 y, f;
        double err;               // <= 1: accepted
        double grow;              // next step / h after an accepted step
        double retry;             // step to retry / h after a rejected one
        SlipRadauPolynomial poly; // an implicit step's collocation polynomial (h = 0: explicit)
    };
    Trial trial(bool implicit, double t0, const Vec4& y0, const Vec4& f0, double h, bool refine);
    bool isStiff(double tau, double rho) const;
    Step slaved(double end);
    Vec3 rhsSlaved(double tau, const Vec3& z);
    Vec2 slavedDirection(double tau, const Vec2& a, double n, double rho) const;
    bool isSlaved(double tau, const Vec4& y) const;
    bool onManifold(double tau, const Vec4& y, double angle) const;
    Approach approachStop(double end);
    Step afterStop();
    double locate(auto&& fdf, double lo, double hi, double flo, double fhi);
    bool collapseIn(const Vec4& yEnd, int& comp, double& sign) const;
    Step collapse(double tau, const Vec4& y, int comp);

    void moveTo(double tau, const Vec4& y);
    double edge(int c) const;
    void extremaWithin(const StepExtrema& ex);
    double overshootWithin(const StepExtrema& ex) const;
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
    double hNext_ = 0;             // step proposal in tau
    double slipPeak_ = 0;          // largest |u| of the current slip (scale of the stop floor)
    double startLength_ = 0;       // first step of a slaved slip
    double slavedSpeed_ = 0;       // below this |u| a slip may be slaved
    SlipRadauPolynomial lastPoly_; // the last accepted step's (h = 0: it was explicit)
    // The last accepted step of the full equations (it ended at fsalT_), for the predictive
    // step control.
    struct {
        double h = 0.0, err = 0.0; // err floored at 1e-2
        bool implicit = false;
    } lastStep_;
    double stiffSpeed_ = 0; // over mu n: below it a slip takes implicit steps
    double fsalT_ = -1.0;   // the last accepted step's end, state and derivative
    Vec4 fsalY_ = Vec4::Zero(), fsalF_ = Vec4::Zero();
    // The current window [winStart_, winEnd_] and its onset roots (scanned when needed); kept
    // across windows so that no window allocates.
    double winStart_ = 0, winEnd_ = 0;
    bool cutsKnown_ = false;
    std::vector<double> cuts_, roots_;
};

Vec4 PlanarRun::rhs(double tau, const Vec4& y) {
    ++r_.slab.work.accelEvaluations;
    const Vec2 a = m_.accel(tau);
    const double n = m_.normal(tau);
    const double rho = norm2(y[2], y[3]);
    double ex = 0, ey = 0;
    if (rho > 0.0) {
        ex = y[2] / rho;
        ey = y[3] / rho;
    } else if (const double am = norm2(a.x, a.y); am > 0.0) {
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
    const double norm = norm2(z[0], z[1]);
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
    slipPeak_ = std::max(slipPeak_, norm2(y[2], y[3]));
    if (o_.recordPath) r_.path.push_back({tau, y[0], y[1], y[2], y[3], slipping_});
}

// Where slope(x), of sign `start` at x = 0 and of the other at 1, changes sign: bisection.
double signChangeOnStep(auto&& slope, double start) {
    double lo = 0.0, hi = 1.0;
    for (int i = 0; i < 60 && hi - lo > 1e-16; ++i) {
        const double mid = 0.5 * (lo + hi);
        slope(mid)* start > 0.0 ? lo = mid : hi = mid;
    }
    return 0.5 * (lo + hi);
}

std::optional<Extremum> hermiteExtremum(double h, const Vec4& y0, const Vec4& y1, int c) {
    const double p0 = y0[c], p1 = y1[c], m0 = h * y0[c + 2], m1 = h * y1[c + 2];
    if (!(m0 * m1 < 0.0)) return std::nullopt;
    // p'(s) = a s^2 + b s + m0 on [0, 1] changes sign once.
    const double a = 6.0 * (p0 - p1) + 3.0 * (m0 + m1), b = 6.0 * (p1 - p0) - 4.0 * m0 - 2.0 * m1;
    const double t = signChangeOnStep([&](double x) { return (a * x + b) * x + m0; }, m0),
                 t2 = t * t, t3 = t2 * t;
    return Extremum{(2 * t3 - 3 * t2 + 1) * p0 + (t3 - 2 * t2 + t) * m0 + (-2 * t3 + 3 * t2) * p1 +
                        (t3 - t2) * m1,
                    t};
}

// The same from an implicit step's collocation polynomial (error O(h^6)): the cubic's O(h^4)
// had moved the peaks by up to 5e-7 relative once the implicit steps grew longer.
std::optional<Extremum> collocationExtremum(const SlipRadauPolynomial& p, const Vec4& y0,
                                            const Vec4& y1, int c) {
    const double u0 = y0[c + 2];
    if (!(u0 * y1[c + 2] < 0.0)) return std::nullopt;
    const double x = signChangeOnStep([&](double xx) { return p.at(xx)[c]; }, u0);
    return Extremum{y0[c] + p.displacement(x)[c], x};
}

StepExtrema stepExtrema(double h, const Vec4& y0, const Vec4& y1, const SlipRadauPolynomial& p) {
    if (p.h > 0.0) return {collocationExtremum(p, y0, y1, 0), collocationExtremum(p, y0, y1, 1)};
    return {hermiteExtremum(h, y0, y1, 0), hermiteExtremum(h, y0, y1, 1)};
}

// The wall edge of displacement component c: the bearing limit across, Θ along the walls.
double PlanarRun::edge(int c) const {
    return c == 0 ? m_.params().limit : m_.params().theta;
}

// Max |dx| and |dy| inside an accepted step, not the step ends only.
void PlanarRun::extremaWithin(const StepExtrema& ex) {
    if (ex[0]) r_.slab.maxAbsDelta = std::max(r_.slab.maxAbsDelta, std::abs(ex[0]->value));
    if (ex[1]) r_.maxAbsDeltaY = std::max(r_.maxAbsDeltaY, std::abs(ex[1]->value));
}

// A step whose ends are inside the walls can still pass an edge between them and come back:
// a grazing collapse that a check of the step's end misses. The fraction of the step at which
// the interpolant's extremum lies beyond an edge (the step is then retaken to end there, where
// the end check sees the collapse and locates it), or 0 when it stays inside.
double PlanarRun::overshootWithin(const StepExtrema& ex) const {
    double first = 0.0;
    for (int c = 0; c < 2; ++c)
        if (ex[c] && std::abs(ex[c]->value) > edge(c) && ex[c]->fraction > 0.0)
            first = first > 0.0 ? std::min(first, ex[c]->fraction) : ex[c]->fraction;
    return first;
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
    // First step of a slaved slip: short against the horizontal time scale (the step control
    // takes over from there).
    startLength_ = m_.horizontalTimeScale() / 250.0;
    // Slaved slips up to |u| = 1e-5 at the default rtol 1e-10: the neglected terms of the
    // manifold move the displacement by O(|u|^3) per unit time, so the bound follows rtol^(1/3)
    // (measured on the golden grids: tau_c within 3.3e-10 at 1e-5, 7.7e-10 at 2e-5, 2.6e-9 at
    // 4e-5 and at 1e-4, which saves only a tenth more).
    slavedSpeed_ = std::clamp(1e-5 * std::cbrt(o_.relTol / 1e-10), 1e-7, 1e-4);
    stiffSpeed_ = 0.04 * mu_ * m_.horizontalTimeScale(); // see isStiff
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

// One window of the time line: find lift-off in it, then alternate stuck and sliding stretches.
// The onset roots (|a_h| = mu n) matter only while the slab is stuck or slaved (whose quadrature
// needs a fixed sign of |a_h| - mu n): they are scanned for then, once per window; a slip
// integrated by the explicit method crosses them as any other time.
PlanarRun::Step PlanarRun::window(double w0, double w1) {
    CrossingScanWork scan;
    double wEnd = w1;
    bool lifts = false;
    if (m_.mayLiftOn(w0, w1)) {
        roots_.clear();
        levelCrossings(
            [&](double t, double& f, double& df) {
                f = -m_.normal(t);
                df = -m_.normalSlope(t);
            },
            w0, w1, kOnsetSub, roots_, scan);
        if (!roots_.empty()) {
            wEnd = roots_.front();
            lifts = true;
        }
    }
    addScanWork(scan);
    winStart_ = w0;
    winEnd_ = wEnd;
    cutsKnown_ = false;
    while (slipping_ || t_ < wEnd) {
        if (!slipping_) {
            const double onset = nextOnset(std::max(t_, w0));
            if (!(onset < wEnd)) break;
            // Slip onset: the slab lags the walls and starts along -a_h.
            t_ = onset;
            slipping_ = true;
            slipPeak_ = 0.0;
            y_[2] = y_[3] = 0.0;
            ++r_.slab.slipIntervals;
            if (!event(EventKind::SlipOnset)) return Step::Done;
        }
        if (slipTo(wEnd) == Step::Done) return Step::Done;
        if (slipping_ && t_ >= wEnd) break;
    }
    if (!slipping_) t_ = std::max(t_, wEnd);
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

void PlanarRun::addScanWork(const CrossingScanWork& scan) {
    r_.slab.work.accelEvaluations += scan.evaluations;
    r_.slab.work.rootIterations += scan.iterations;
}

// The window's onset roots, scanned on first use: cuts_ = {start, roots..., end}.
void PlanarRun::scanCuts() {
    if (cutsKnown_) return;
    cutsKnown_ = true;
    cuts_.clear();
    cuts_.push_back(winStart_);
    CrossingScanWork scan;
    if (!m_.quietOn(winStart_, winEnd_))
        levelCrossings(
            [&](double t, double& f, double& df) {
                f = m_.onsetMargin(t);
                df = m_.onsetMarginSlope(t);
            },
            winStart_, winEnd_, kOnsetSub, cuts_, scan);
    cuts_.push_back(winEnd_);
    addScanWork(scan);
}

// The first time at or after `from` in the window where the slab slips (|a_h| > mu n on the
// piece that follows); winEnd_ when there is none.
double PlanarRun::nextOnset(double from) {
    if (m_.quietOn(from, winEnd_)) return winEnd_;
    scanCuts();
    for (std::size_t i = 0; i + 1 < cuts_.size(); ++i) {
        const double lo = std::max(cuts_[i], from), hi = cuts_[i + 1];
        if (hi > lo && m_.onsetMargin(0.5 * (lo + hi)) > 0.0) return lo;
    }
    return winEnd_;
}

// The first onset root after tau in the window (winEnd_ when none): where a slaved stretch ends.
double PlanarRun::nextCut(double tau) {
    scanCuts();
    const auto it = std::upper_bound(cuts_.begin(), cuts_.end(), tau);
    return it == cuts_.end() ? winEnd_ : *it;
}

// Slides from t_ to end, or until the slab sticks (then returns with slipping_ false).
PlanarRun::Step PlanarRun::slipTo(double end) {
    bool rejected = true, lastImplicit = false;
    while (t_ < end) {
        const double rho = norm2(y_[2], y_[3]);
        if (isSlaved(t_, y_)) {
            const Step s = slaved(end);
            if (s == Step::Done || !slipping_) return s;
            continue;
        }
        // The derivative at the state an accepted step ended on is that step's last stage (FSAL).
        const Vec4 f0 = t_ == fsalT_ && y_ == fsalY_ ? fsalF_ : rhs(t_, y_);
        const double d = -(y_[2] * f0[2] + y_[3] * f0[3]) / rho; // -d|u|/dtau
        double h = std::min(hNext_ > 0.0 ? hNext_ : rho / (mu_ + 1.0), end - t_);
        const bool implicit = isStiff(t_, rho);
        const bool stopAhead = d > 0.0 && rho <= d * h; // a stop predicted within the step
        if (stopAhead && implicit && rho > slavedSpeed_ && onManifold(t_, y_, 0.05)) {
            // On the slow manifold |u| falls about linearly while its direction follows -a_h;
            // the implicit steps go down to the slaved speed, which locates the stop.
            h = 0.5 * rho / d;
        } else if (stopAhead) {
            // Off it: go on in s = ln|u|.
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
        const Trial st = trial(implicit, t_, y_, f0, h, rejected || implicit != lastImplicit);
        lastImplicit = implicit;
        rejected = !(st.err <= 1.0);
        if (rejected) {
            ++r_.slab.work.restarts;
            hNext_ = h * st.retry;
            if (hNext_ < 1e-15 * std::max(1.0, t_)) return fail("step size underflow in a slip");
            continue;
        }
        int comp = -1;
        double sign = 0;
        const bool endsOutside = collapseIn(st.y, comp, sign);
        const StepExtrema extrema = stepExtrema(h, y_, st.y, st.poly);
        if (const double s = endsOutside ? 0.0 : overshootWithin(extrema);
            s > 0.0 && s * h > 1e-15 * std::max(1.0, t_)) {
            ++r_.slab.work.restarts;
            hNext_ = s * h * (1.0 + 1e-9); // just past the extremum, outside the edge
            continue;
        }
        if (endsOutside) {
            const double lim = edge(comp);
            const Vec4 y0 = y_;
            const double t0 = t_;
            const double tc = locate(
                [&](double t, double& f, double& df) {
                    const Trial s = trial(implicit, t0, y0, f0, t - t0, true);
                    f = sign * s.y[comp] - lim;
                    df = sign * s.y[comp + 2];
                },
                t0, t0 + h, sign * y0[comp] - lim, sign * st.y[comp] - lim);
            return collapse(tc, trial(implicit, t0, y0, f0, tc - t0, true).y, comp);
        }
        if (st.y[2] * y_[2] + st.y[3] * y_[3] < 0.0) {
            // The velocity turned over within one step: it passed a stop; retake it shorter so
            // the stop is approached in s.
            ++r_.slab.work.restarts;
            hNext_ = 0.5 * h;
            continue;
        }
        const bool truncated = h < hNext_;
        extremaWithin(extrema);
        double grow = h * st.grow;
        if (fsalT_ == t_ && lastStep_.implicit == implicit) {
            const double errPrev = lastStep_.err, hPrev = lastStep_.h;
            grow =
                std::min(grow, h * (implicit ? radau::predictiveFactor(h, st.err, hPrev, errPrev)
                                             : dop853PredictiveFactor(h, st.err, hPrev, errPrev)));
        }
        lastStep_ = {h, std::max(1e-2, st.err), implicit};
        moveTo(t_ + h, st.y);
        fsalT_ = t_;
        fsalY_ = y_;
        fsalF_ = st.f;
        lastPoly_ = st.poly;
        hNext_ = truncated ? std::max(hNext_, grow) : grow;
    }
    return Step::Continue;
}

// One step of the slip equations from (t0, y0), explicit (DOP853) or implicit (Radau IIA),
// with its error norm and the factors for the next step or the retry.
PlanarRun::Trial PlanarRun::trial(bool implicit, double t0, const Vec4& y0, const Vec4& f0,
                                  double h, bool refine) {
    const Vec4 absTol = Vec4::Constant(o_.absTol);
    if (implicit) {
        // The previous step's polynomial is used only when it ended at t0 (slipRadauStep checks).
        const SlipRadauStep st = slipRadauStep(m_, t0, y0, f0, h, absTol, o_.relTol, refine,
                                               lastPoly_.h > 0.0 ? &lastPoly_ : nullptr);
        r_.slab.work.accelEvaluations += st.evaluations;
        r_.slab.work.rootIterations += st.newton;
        const double factor = radau::stepFactor(st.err, st.newton, kSlipRadauMaxNewton);
        return {st.y, st.f, st.err, factor, std::isfinite(st.err) ? factor : 0.5, st.poly};
    }
    const auto st =
        dop853Step<4>([&](double t, const Vec4& y) { return rhs(t, y); }, t0, y0, f0, h);
    const double err = dop853ErrorNorm<4>(st, y0, absTol, o_.relTol);
    return {st.y, st.f, err, dop853StepFactor(err), dop853RetryStep(h, err) / h, {}};
}

// Whether a slip at speed rho is left to the implicit step: the explicit one's stability bound,
// about 6 |u| / (mu n) (the Jacobian's eigenvalue is -mu n / |u|), then falls below a few
// hundredths of the horizontal time scale T, about its accuracy step at the default tolerance.
// With the five-stage Radau IIA step the threshold |u| < 0.04 mu n T costs least on the 33x33
// bench grid (instructions: 0.03 and 0.06 within 1 %, 0.02 3 % and 0.01 9 % more; docs/theory.md
// §6.5); with three stages 0.02 had been the fastest.
bool PlanarRun::isStiff(double tau, double rho) const {
    return rho < stiffSpeed_ * m_.normal(tau);
}

bool PlanarRun::collapseIn(const Vec4& y, int& comp, double& sign) const {
    if (std::abs(y[0]) > edge(0)) {
        comp = 0;
        sign = y[0] > 0.0 ? 1.0 : -1.0;
        return true;
    }
    if (std::abs(y[1]) > edge(1)) {
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

// Slaved slip (docs/theory.md §6.5): while |u| is small the direction of u relaxes to its slow
// manifold at rate |a|/|u|, far faster than anything else moves, and an explicit method would
// crawl at steps of about |u| / |a| (stability, not accuracy). On the manifold u lags -a_h by
//   phi = -theta_a' |u| / (|a| + m),  m = |a_h| - mu n  (theta_a: the direction of a_h),
// exact while the coefficients are frozen (|u| then grows or shrinks linearly and phi with it);
// the neglected terms are O((Omega |u| / |a|)^2) relative. The reduced state (|u|, dx, dy) is
// smooth: |u|' = |a| cos phi - mu n, delta' = |u| (-a_h / |a|) rotated by phi. It is integrated
// by the same DOP853 with steps set by the tolerance, not by |u|.
Vec3 PlanarRun::rhsSlaved(double tau, const Vec3& z) {
    ++r_.slab.work.accelEvaluations;
    const Vec2 a = m_.accel(tau);
    const double n = m_.normal(tau);
    const Vec2 dir = slavedDirection(tau, a, n, z[0]);
    const double speedRate = -mu_ * n - (a.x * dir.x + a.y * dir.y);
    Vec3 f;
    f << speedRate, z[0] * dir.x, z[0] * dir.y;
    return f;
}

// The unit direction of u on the slow manifold at speed rho (-a_h / |a| turned by phi).
Vec2 PlanarRun::slavedDirection(double tau, const Vec2& a, double n, double rho) const {
    const Vec2 sl = m_.accelSlope(tau);
    const double am = norm2(a.x, a.y);
    if (!(am > 0.0)) return {0.0, 0.0};
    const double turn = (a.x * sl.y - a.y * sl.x) / (am * am); // theta_a'
    const double relax = 2.0 * am - mu_ * n;                   // |a| + m
    const double phi = -turn * rho / std::max(relax, 0.5 * am);
    const double ex = -a.x / am, ey = -a.y / am, c = std::cos(phi), sn = std::sin(phi);
    return {ex * c - ey * sn, ex * sn + ey * c};
}

PlanarRun::Step PlanarRun::slaved(double end) {
    const double rhoExit = 2.0 * slavedSpeed_;
    Vec3 z;
    z << norm2(y_[2], y_[3]), y_[0], y_[1];
    auto f = [&](double t, const Vec3& zz) { return rhsSlaved(t, zz); };
    // |u| is tiny here and a stop's time is |u| / |m| off per unit of error in |u|: its absolute
    // tolerance is scaled down with the largest slaved speed.
    Vec3 absTol = Vec3::Constant(o_.absTol);
    absTol[0] = 1e-3 * o_.absTol;
    Vec3 f0 = f(t_, z);
    double h = startLength_;
    while (t_ < end) {
        // On a piece between onset roots the sign of |u|' is fixed: |u| has no interior zero.
        const double t0 = t_, pieceEnd = std::min(end, nextCut(t0)),
                     hh = std::min(h, pieceEnd - t0);
        if (++r_.slab.work.steps > o_.maxSteps) return fail("step limit reached");
        const auto st = dop853Step<3>(f, t0, z, f0, hh);
        const double err = dop853ErrorNorm<3>(st, z, absTol, o_.relTol);
        if (!(err <= 1.0)) {
            ++r_.slab.work.restarts;
            h = dop853RetryStep(hh, err);
            if (h < 1e-15 * std::max(1.0, t0)) return fail("step size underflow in a slaved slip");
            continue;
        }
        if (!(st.y[0] > 0.0)) {
            // The speed reaches zero in this step: a stop, located on re-taken steps.
            const double ts = z[0] <= 0.0
                                  ? t0
                                  : locate(
                                        [&](double t, double& g, double& dg) {
                                            const Vec3 zz = dop853Step<3>(f, t0, z, f0, t - t0).y;
                                            g = zz[0];
                                            dg = f(t, zz)[0];
                                        },
                                        t0, t0 + hh, z[0], st.y[0]);
            const Vec3 zs = ts == t0 ? z : Vec3(dop853Step<3>(f, t0, z, f0, ts - t0).y);
            Vec4 y;
            y << zs[1], zs[2], 0.0, 0.0;
            moveTo(ts, y);
            return afterStop();
        }
        const bool truncated = hh < h;
        const double grow = hh * dop853StepFactor(err);
        h = truncated ? std::max(h, grow) : grow;
        z = st.y;
        f0 = st.f;
        const double t1 = t0 + hh;
        const Vec2 a1 = m_.accel(t1);
        const Vec2 dir = slavedDirection(t1, a1, m_.normal(t1), z[0]);
        Vec4 y;
        y << z[1], z[2], z[0] * dir.x, z[0] * dir.y;
        moveTo(t1, y);
        if (z[0] > rhoExit) {
            // Back to the full equations; their first step must resolve the relaxation.
            hNext_ = 0.5 * z[0] / std::max(norm2(a1.x, a1.y), 1e-300);
            break;
        }
    }
    return Step::Continue;
}

// True when |u| is small, the manifold attracts (|a| + m >= |a| / 2) and u lies on it (within
// 1e-3 rad: projecting onto it moves the displacement by about |u|^2 1e-3 / |a|), so that the
// slip is slaved.
bool PlanarRun::isSlaved(double tau, const Vec4& y) const {
    return norm2(y[2], y[3]) <= slavedSpeed_ && onManifold(tau, y, 1e-3);
}

// True when the manifold attracts (|a| + m >= |a| / 2) and u lies on it within `angle` rad.
bool PlanarRun::onManifold(double tau, const Vec4& y, double angle) const {
    const double rho = norm2(y[2], y[3]);
    if (rho == 0.0) return true;
    const Vec2 a = m_.accel(tau);
    const double am = norm2(a.x, a.y);
    const double n = m_.normal(tau);
    if (!(am > 0.0) || 2.0 * am - mu_ * n < 0.5 * am) return false;
    const Vec2 dir = slavedDirection(tau, a, n, rho);
    return std::abs(dir.x * y[3] - dir.y * y[2]) <= angle * rho &&
           dir.x * y[2] + dir.y * y[3] > 0.0;
}

// Approach of a stop in s = ln|u|, from the current state (|u| > 0, |u| decreasing).
PlanarRun::Approach PlanarRun::approachStop(double end) {
    const double tEntry = t_;
    double rho = norm2(y_[2], y_[3]);
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
        const double r = std::exp(ss), nrm = norm2(zz[0], zz[1]);
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
        const double dNew = dissipationRate(tauNew, st.y[0] / norm2(st.y[0], st.y[1]),
                                            st.y[1] / norm2(st.y[0], st.y[1]));
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
            const double lim = edge(comp);
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
        const double nrm = norm2(z[0], z[1]);
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
        if (dNew < 1e-3 * (mu_ * m_.normal(tauNew) + norm2(a.x, a.y))) {
            moveTo(tauNew, toTau(z, s));
            hNext_ = 0.1 * std::exp(s) / (mu_ * m_.normal(t_) + norm2(a.x, a.y) + 1e-300);
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
