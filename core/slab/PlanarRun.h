// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One run of the planar solver (core/slab/PlanarSolver.h; docs/theory.md §5, §6.5): the class is
// private to the solver and its methods live in one file per concern:
//   PlanarRun.cpp           the time line: windows, slip onsets, events, results
//   PlanarTimeEvents.cpp    the time events' scans (onset, lift-off) on a window
//   PlanarSlip.cpp          a slip's steps: DOP853, or Radau IIA where the slip is stiff
//   PlanarSlaved.cpp        the slaved slip on the slow manifold at small |u|
//   PlanarStopApproach.cpp  the approach of a stop in s = ln|u|
// Every event comes from the table in core/slab/PlanarEvents.h and state events are located by
// its one locator on the step's dense output.

#include "core/numerics/Dop853.h"
#include "core/numerics/LevelCrossings.h"
#include "core/slab/PlanarEvents.h"
#include "core/slab/PlanarSolver.h"
#include "core/slab/SlipRadau.h"

#include <vector>

namespace kinstab::planar {

using Vec4 = OdeVec<4>; // (dx, dy, ux, uy) in tau
using Vec5 = OdeVec<5>; // (ex, ey, tau - tau_entry, dx, dy) in s = ln|u|
using Vec3 = OdeVec<3>; // (|u|, dx, dy) in tau, on the slow manifold

// The solver's guards and thresholds, each with why it has its value.
// Keeps a quotient by a rate that may be exactly 0 (|a_h|, the dissipation D) finite: far below
// any rate the motion has (accelerations and D are O(1e-16) at the least, rounding of O(1)).
inline constexpr double kRateFloor = 1e-300;
// A step below this times max(1, tau) is lost in the rounding of tau: the run fails.
inline constexpr double kStepUnderflow = 1e-15;
// Sub-intervals of a window scanned for time events (each holds at most one extremum of
// |a_h| - mu n: a window is at most a half-period of each component or one record sample). A
// window shorter than the horizontal time scale T takes fewer, none longer than T / kTimeEventSub
// (a record sample of 0.1 tau takes one where it took eight: the scans were a tenth of a run).
inline constexpr int kTimeEventSub = 8;
// A slip's stop is taken once |u| is below this times its peak speed: the rest of the way is
// |u| / D, in error by O(|u|^2) (F7 (c), docs/theory.md §6.5).
inline constexpr double kStopFloor = 1e-14;
// In s = ln|u|: a rejected step shrinks by kLogShrink; below kMinLogStep |u| turns before it
// reaches 0 and the slip goes back to tau with a first step of kReentryStep |u| / rate (a tenth
// of the time |u| takes to change by itself).
inline constexpr double kLogShrink = 0.25;
inline constexpr double kMinLogStep = 1e-12;
inline constexpr double kReentryStep = 0.1;
// D below this fraction of mu n + |a_h|: the speed is about to turn and dtau/ds = -|u|/D blows up.
inline constexpr double kTurnRatio = 1e-3;
// The first step of a slaved slip: the horizontal time scale over this (the step control takes
// over from there).
inline constexpr double kSlavedStartDivisions = 250.0;
// Slaved slips up to |u| = kSlavedSpeed at the default rtol 1e-10 (kSlavedSpeedRtol): the
// neglected terms of the manifold move the displacement by O(|u|^3) per unit time, so the bound
// follows rtol^(1/3) within [kSlavedSpeedMin, kSlavedSpeedMax] (measured on the golden grids:
// tau_c within 3.3e-10 at 1e-5, 7.7e-10 at 2e-5, 2.6e-9 at 4e-5 and at 1e-4, which saves only a
// tenth more).
inline constexpr double kSlavedSpeed = 1e-5, kSlavedSpeedRtol = 1e-10;
inline constexpr double kSlavedSpeedMin = 1e-7, kSlavedSpeedMax = 1e-4;
// A slaved slip returns to the full equations above this multiple of the slaved speed (the gap
// keeps a slip from flipping between the two forms) with a first step of kRelaxStep |u| / |a_h|,
// which resolves the direction's relaxation.
inline constexpr double kSlavedExit = 2.0, kRelaxStep = 0.5;
// |u| is tiny while slaved and a stop's time is |u| / |m| off per unit of error in |u|: its
// absolute tolerance is the others' times this.
inline constexpr double kSlavedSpeedTol = 1e-3;
// u within kSlavedAngle rad of the manifold counts as on it (projecting onto it moves the
// displacement by about |u|^2 kSlavedAngle / |a|); implicit steps may run a slip down to the
// slaved speed when within kImplicitStopAngle.
inline constexpr double kSlavedAngle = 1e-3, kImplicitStopAngle = 0.05;
// The manifold attracts while |a| + m >= kAttraction |a| (m = |a_h| - mu n).
inline constexpr double kAttraction = 0.5;
// A slip below kStiffSpeed mu n T takes implicit steps (see PlanarRun::isStiff).
inline constexpr double kStiffSpeed = 0.04;
// Floor of the error norm remembered for the predictive step control (Gustafsson's controller
// divides by it).
inline constexpr double kErrorFloor = 1e-2;
// A step retaken to end at an interpolant's extremum beyond an edge ends this fraction past it,
// outside the edge.
inline constexpr double kPastExtremum = 1e-9;
// A stop predicted inside a step on the manifold: the implicit step goes half the way to it.
inline constexpr double kStopHalfway = 0.5;

// Where a velocity component changes sign inside a step, the extremum of that displacement on
// the step's interpolant: its value and where it lies as a fraction of the step.
struct Extremum {
    double value = 0.0;
    double fraction = 0.0;
};
using StepExtrema = std::array<std::optional<Extremum>, 2>; // dx, dy; none: keeps its sign

// The extrema of dx and dy inside an accepted step from y0 to y1 of length h: from the implicit
// step's collocation polynomial p when it has one (p.h > 0), else from the cubic Hermite
// interpolant.
StepExtrema stepExtrema(double h, const Vec4& y0, const Vec4& y1, const SlipRadauPolynomial& p);

class PlanarRun {
public:
    PlanarRun(const SlabModel2D& m, const PlanarOptions& o, PlanarRecorder* recorder);
    PlanarResult run();

private:
    enum class Step { Continue, Done };
    enum class Approach { Stopped, Exited, ReachedEnd, Done };
    // What the slip loop does after a stop was predicted within its next step.
    enum class Flow { TakeStep, Again, Return, Done };
    struct Trial {
        Vec4 y, f;
        double err;               // <= 1: accepted
        double grow;              // next step / h after an accepted step
        double retry;             // step to retry / h after a rejected one
        SlipRadauPolynomial poly; // an implicit step's collocation polynomial (h = 0: explicit)
    };
    // The state at the start of s = ln|u| stepping, and the way back to tau.
    struct LogState {
        double tEntry, s, sFloor;
        Vec5 z, fz;
    };

    // Time line (PlanarRun.cpp).
    bool startsLifted();
    Step window(double w0, double w1);
    Step startSlip(double onset);
    void moveTo(double tau, const Vec4& y);
    bool event(EventKind kind);
    Step finish(Outcome o);
    Step fail(const std::string& why);

    // Time events (PlanarTimeEvents.cpp).
    bool scanLiftOff(double w0, double w1, double& wEnd);
    void scanTimeEvent(const TimeEvent& e, double lo, double hi, std::vector<double>& out,
                       double from = -INFINITY);
    int onsetSubIntervals(double lo, double hi) const;
    void scanCuts(double from, bool quiet);
    double nextOnset(double from);
    double nextCut(double tau);
    bool quietOn(double lo, double hi);
    bool quietOnModel(double lo, double hi); // quietOn past its memory
    bool quietAfter(double tau);

    // Slip (PlanarSlip.cpp).
    Vec4 rhs(double tau, const Vec4& y);
    Step slipTo(double end);
    Flow stopAhead(double end, double d, double rho, bool implicit, double& h);
    Step step(bool implicit, const Vec4& f0, double h);
    Trial trial(bool implicit, double t0, const Vec4& y0, const Vec4& f0, double h, bool refine);
    bool isStiff(double tau, double rho) const;
    bool retakeForOvershoot(const StepExtrema& ex, double h, bool endsOutside);
    Step collapseInStep(const StateEvent& e, bool implicit, const Vec4& f0, double h,
                        const Vec4& yEnd);
    void accept(const Trial& st, double h, bool implicit, const StepExtrema& extrema);
    double edge(int c) const;
    double overshootWithin(const StepExtrema& ex) const;
    void extremaWithin(const StepExtrema& ex);
    Step collapse(double tau, const Vec4& y, const StateEvent& e);

    // Slaved slip (PlanarSlaved.cpp).
    Step slaved(double end);
    Step slavedStop(double t0, double hh, const Vec3& z, const Vec3& f0, const Vec3& zEnd);
    bool leaveSlaved(double t1, const Vec3& z, double rhoExit);
    Vec3 rhsSlaved(double tau, const Vec3& z);
    Vec2 slavedDirection(const Vec2& a, const Vec2& slope, double n, double rho) const;
    bool isSlaved(double tau, const Vec4& y) const;
    bool onManifold(double tau, const Vec4& y, double angle) const;

    // Stop approach (PlanarStopApproach.cpp).
    Vec5 rhsS(double s, const Vec5& z);
    double dissipationRate(double tau, double ex, double ey); // D = mu n + a.e = -d|u|/dtau
    Approach approachStop(double end);
    LogState enterLog();
    Vec4 fromLog(const Vec5& z, double s) const;
    Vec5 logRestep(const LogState& l, double sTarget);
    Approach stopAtFloor(const LogState& l);
    Approach leaveLog(double tau, const Vec4& y, double speed, double accel);
    Approach logPieceEnd(const LogState& l, double h, const Vec5& zEnd, double end);
    Approach logCollapse(const LogState& l, double h, const Vec5& zEnd, const StateEvent& wall);
    Step afterStop();

    const SlabModel2D& m_;
    const PlanarOptions& o_;
    PlanarRecorder* recorder_; // null: nothing kept beyond the result
    double mu_;
    WallEvents walls_;
    PlanarResult r_;
    double t_ = 0;
    Vec4 y_ = Vec4::Zero();
    bool slipping_ = false;
    double hNext_ = 0;             // step proposal in tau
    double slipPeak_ = 0;          // largest |u| of the current slip (scale of the stop floor)
    double timeScale_ = 0;         // the horizontal time scale T
    double startLength_ = 0;       // first step of a slaved slip
    double slavedSpeed_ = 0;       // below this |u| a slip may be slaved
    SlipRadauPolynomial lastPoly_; // the last accepted step's (h = 0: it was explicit)
    // The last accepted step of the full equations (it ended at fsalT_), for the predictive
    // step control.
    struct {
        double h = 0.0, err = 0.0; // err floored at kErrorFloor
        bool implicit = false;
    } lastStep_;
    double stiffSpeed_ = 0;             // over mu n: below it a slip takes implicit steps
    radau::EstimateTolerance radauTol_; // the implicit steps' estimate tolerances
    double fsalT_ = -1.0;               // the last accepted step's end, state and derivative
    Vec4 fsalY_ = Vec4::Zero(), fsalF_ = Vec4::Zero();
    // The slip loop's memory between steps: whether the last trial was rejected or implicit.
    bool rejected_ = true, lastImplicit_ = false;
    // The current window [winStart_, winEnd_] and its onset roots (scanned when needed); kept
    // across windows so that no window allocates.
    double winStart_ = 0, winEnd_ = 0;
    bool cutsKnown_ = false;
    // Where the model's bounds were asked ahead (see quietOn, quietAfter).
    struct {
        double lo = 0.0, hi = -1.0;
    } quietSpan_;
    double loudSpanEnd_ = -1.0, loudUntil_ = -1.0;
    struct {
        double lo = NAN, hi = NAN;
    } lastLoud_; // the last span quietOn found loud
    std::vector<double> cuts_, roots_;
};

} // namespace kinstab::planar
