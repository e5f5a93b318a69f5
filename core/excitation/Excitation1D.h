// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What the event-driven 1-DOF solver needs to know about a base acceleration a(tau), in g,
// as a function of dimensionless time. Implementations: EnvelopedSine (closed form),
// and piecewise-linear recorded motions.

#include <array>
#include <cmath>
#include <limits>

namespace kinstab {

// a(tau) = a0 + slope (tau - t0) on a stretch of time where the motion is one linear piece,
// written with the arithmetic accel() uses there, so that a caller evaluating it gets the same
// bits as accel() and accelSlope() without finding the piece again.
struct LinearPiece {
    double a0 = 0, t0 = 0, slope = 0;
    double accel(double tau) const { return a0 + slope * (tau - t0); }
};

// Times where a(tau) crosses a level inside one segment, increasing.
struct Crossings {
    std::array<double, 4> t{};
    int n = 0;
    void add(double tau) { t[static_cast<std::size_t>(n++)] = tau; }
};

// a and its first two derivatives at one time; the derivatives NaN where not known.
struct AccelAt {
    double a = 0;
    double da = std::numeric_limits<double>::quiet_NaN();
    double d2a = std::numeric_limits<double>::quiet_NaN();
};

class Excitation1D {
public:
    virtual ~Excitation1D() = default;
    virtual double accel(double tau) const = 0;
    virtual double accelSlope(double tau) const = 0;
    // Integral of a over [t0, t1].
    virtual double velocityChange(double t0, double t1) const = 0;
    // velocityChange(t0, t1) and accel(t1) at once: the event search needs both at every
    // iteration, and a closed form can share its exponentials between them.
    virtual double velocityChangeAndAccel(double t0, double t1, double& accelAtT1) const {
        accelAtT1 = accel(t1);
        return velocityChange(t0, t1);
    }
    // velocityChange(t0, t1) with a, a' and a'' at t1 from one evaluation: a stop search takes
    // Halley's steps where a closed form gives the two slopes (docs/theory.md §6.3), Newton's
    // where they are not known (NaN, as here).
    virtual double velocityChangeAndSlopes(double t0, double t1, AccelAt& at) const {
        at = AccelAt{};
        return velocityChangeAndAccel(t0, t1, at.a);
    }
    // Integral over [t0, t1] of (integral of a over [t0, s]) ds.
    virtual double displacementChange(double t0, double t1) const = 0;
    // Both changes at once: the end of every slip piece needs both, and a closed form can
    // share its exponentials between them.
    virtual double velocityAndDisplacementChange(double t0, double t1, double& dx) const {
        dx = displacementChange(t0, t1);
        return velocityChange(t0, t1);
    }
    // Both changes and accel(t1) at once: a slip piece's end state and the slope of its
    // velocity there, which a stop search between two piece ends needs at both ends.
    virtual double changesAndAccel(double t0, double t1, double& dx, double& accelAtT1) const {
        accelAtT1 = accel(t1);
        return velocityAndDisplacementChange(t0, t1, dx);
    }
    // Time line cut into segments; each segment is small enough that a(tau) crosses any level
    // at most Crossings::t.size() times in it, and crossings() finds them all with a bracket.
    virtual double segmentEnd(double segmentStart) const = 0;
    // All sign changes of a(tau) - level in (segmentStart, segmentEnd), increasing.
    // A level touched but not crossed (a double root) is not a crossing.
    virtual Crossings crossings(double level, double segmentStart, double segmentEnd) const = 0;
    // An upper bound of |a(s)| over all s >= tau: once it is below mu, nothing can start.
    virtual double boundAfter(double tau) const = 0;
    // An upper bound of |a| over [lo, hi], cheap: lets the solver skip quiet segments.
    virtual double boundOn(double lo, double hi) const = 0;
    // +1 or -1 when [lo, hi] (within one segment) lies on one hump of a: a keeps that sign and
    // |a| rises, then falls; 0 when not, or not known without evaluating a.
    virtual int humpSign(double /*lo*/, double /*hi*/) const { return 0; }
    // On a hump: the first time in (lo, hi) where |a| rises (rising) or falls through level > 0;
    // NaN when there is none there. Lets a solver find only the crossing an event needs.
    virtual double humpCrossing(double level, double lo, double hi, bool rising) const;
    // Largest |a| anywhere.
    virtual double peak() const = 0;
    // Evaluations of a or its integrals that this excitation made on the calling thread so far
    // for its own root solves (crossings, hump peaks): a solver adds the change over its run to
    // the evaluations it counts itself, so that its work counter misses none (issue 34).
    virtual long threadEvaluations() const { return 0; }
    // True, with the piece, when a is one linear piece for every tau in [lo, hi) and accel()
    // there computes piece.accel(tau), accelSlope() piece.slope (a recorded motion inside one
    // sample interval); false when not, or not known.
    virtual bool linearOn(double /*lo*/, double /*hi*/, LinearPiece& /*piece*/) const {
        return false;
    }
};

inline double Excitation1D::humpCrossing(double level, double lo, double hi, bool rising) const {
    const int sign = humpSign(lo, hi);
    const Crossings c = crossings(sign * level, lo, hi);
    for (int i = 0; i < c.n; ++i) {
        const double t = c.t[static_cast<std::size_t>(i)];
        if ((sign * accelSlope(t) > 0.0) == rising) return t;
    }
    return std::numeric_limits<double>::quiet_NaN();
}

} // namespace kinstab
