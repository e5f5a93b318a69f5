// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The planar two-degree-of-freedom slab (Furgerson 1980, ch. VI; docs/theory.md §5): relative
// displacement (dx across the walls, dy along them) and relative velocity u, driven by two
// horizontal base accelerations a_x, a_y and a vertical factor n(tau) = 1 + a_z(tau) on the normal
// force. Each excitation is any Excitation1D (enveloped sine, recorded motion), in g of tau = t /
// t*.

#include "core/excitation/EnvelopedSine.h"
#include "core/excitation/Excitation1D.h"
#include "core/slab/SinePairSeries.h"
#include "core/slab/SlabTypes.h"

#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>

namespace kinstab {

// The 1-DOF slab's inputs (mu, limit across the walls, duration) and the limit along the walls.
struct PlanarParams : SlabParams {
    double theta = 20.0; // along the walls: collapse when |dy| > theta = 2 wall length / wall width
};
InputProblem checkPlanarParams(const PlanarParams& p);   // checkSlabParams and Θ
std::string validatePlanarParams(const PlanarParams& p); // empty when fine

struct Vec2 {
    double x = 0, y = 0;
};

// |(x, y)| without std::hypot's guard against overflow: the speeds and accelerations here are
// within a few orders of 1, and hypot cost a tenth of the planar solver's time.
inline double norm2(double x, double y) {
    return std::sqrt(x * x + y * y);
}

class SlabModel2D {
public:
    // ay and az may be null: no motion along the walls, gravity only.
    SlabModel2D(std::shared_ptr<const Excitation1D> ax, std::shared_ptr<const Excitation1D> ay,
                std::shared_ptr<const Excitation1D> az, PlanarParams params);

    // a_h; inline, as the planar solver's innermost call.
    Vec2 accel(double tau) const {
        if (series_) {
            const auto a = series_->accel(tau);
            return {a[0], a[1]};
        }
        return {x_.accel(*ax_, tau), ay_ ? y_.accel(*ay_, tau) : 0.0};
    }
    Vec2 accelSlope(double tau) const; // a_h'
    // a_h and a_h' at once, the same bits as the two calls (the series looked up once: the onset
    // scans, the slaved slip and its exit ask for both).
    void accelAndSlope(double tau, Vec2& a, Vec2& s) const {
        if (series_) {
            std::array<double, 2> av, sv;
            series_->accelAndSlope(tau, av, sv);
            a = {av[0], av[1]};
            s = {sv[0], sv[1]};
            return;
        }
        a = accel(tau);
        s = accelSlope(tau);
    }
    double normal(double tau) const { // n = 1 + a_z
        if (!az_) return 1.0;
        return 1.0 + z_.accel(*az_, tau);
    }
    double normalSlope(double tau) const;
    // The solver works in [lo, hi] next (a window of the time line, inside one segment of each
    // component): a component that is one linear piece on [lo, hi) (a record inside one sample
    // interval) is evaluated from that piece, and at hi from its value there, asked once, without
    // finding its sample interval at every call (issue 34: the lookup was a tenth of a run with a
    // vertical record; the steps and scans that end at hi had still looked it up). The same bits
    // as without (but a slope at a sample time, see WindowPiece); elsewhere, the components'.
    void enterWindow(double lo, double hi) const;
    // g_on = |a_h| - mu n: the slab slips where it is positive (a time-only event).
    double onsetMargin(double tau) const;
    double onsetMarginSlope(double tau) const;
    // Both at once (a_h and n evaluated once), with the same bits as the two calls.
    void onsetMarginAndSlope(double tau, double& g, double& slope) const;
    void liftMarginAndSlope(double tau, double& g, double& slope) const {
        g = liftMargin(tau);
        slope = liftMarginSlope(tau);
    }
    // g_lift = -n: the slab leaves its support where it is positive (a time-only event).
    double liftMargin(double tau) const { return -normal(tau); }
    double liftMarginSlope(double tau) const { return -normalSlope(tau); }
    // True when nothing can start any more after tau: the root-sum-square of both components'
    // bounds is below mu times the least n can be (docs/theory.md §5, "End").
    bool quietAfter(double tau) const;
    // True when nothing can start inside [lo, hi] (cheap rigorous bounds: the components'
    // envelopes, or |a_h| at the middle plus the bound on |a_h'| times the half-length).
    bool quietOn(double lo, double hi) const;
    // True when n may reach 0 inside [lo, hi].
    bool mayLiftOn(double lo, double hi) const {
        return liftPossible_ && az_->boundOn(lo, hi) >= 1.0;
    }
    // Next cut of the time line: the earliest segment end of any component.
    double segmentEnd(double tau) const;
    // Length of the first segment of the horizontal motion (a half-period for a sine): the
    // time scale on which a_h turns.
    double horizontalTimeScale() const;

    const PlanarParams& params() const { return params_; }
    bool hasVertical() const { return az_ != nullptr; }
    bool hasAlongWalls() const { return ay_ != nullptr; }

private:
    // A component's linear piece on the current window [l, h), when it has one, and its value
    // and slope at h (the next piece's there), asked of the component on first use. A window's
    // end that is a sample time can read the piece after it from the double before on
    // (floor(tau / h) rounds up there), and a start the piece before (rounds down: either for
    // 7 % of RSN68's samples at t* 0.099): the piece then covers the window less that double,
    // which is read from the component (without this, such windows read every value from it).
    // At a start so cut the value is the component's, the slope the piece's (the window's side,
    // for scans).
    struct WindowPiece {
        double lo = 0, hi = 0;  // the piece covers [lo, hi); empty: covers nothing
        double windowEnd = NAN; // h, whose value is kept; NaN: no piece
        LinearPiece piece;
        double start = NAN, startAccel = 0, startSlope = 0; // NaN: lo is the window's start
        mutable bool endKnown = false;
        mutable double endAccel = 0, endSlope = 0;
        bool covers(double tau) const { return tau >= lo && tau < hi; }
        double accel(const Excitation1D& a, double tau) const {
            if (covers(tau)) return piece.accel(tau);
            if (tau == windowEnd) return end(a).endAccel;
            return tau == start ? startAccel : a.accel(tau);
        }
        double slope(const Excitation1D& a, double tau) const {
            if (covers(tau)) return piece.slope;
            if (tau == windowEnd) return end(a).endSlope;
            return tau == start ? startSlope : a.accelSlope(tau);
        }
        const WindowPiece& end(const Excitation1D& a) const {
            if (!endKnown) {
                endKnown = true;
                endAccel = a.accel(windowEnd);
                endSlope = a.accelSlope(windowEnd);
            }
            return *this;
        }
        void enter(const Excitation1D* a, double l, double h);
    };
    std::shared_ptr<const Excitation1D> ax_, ay_, az_;
    // Filled by enterWindow; a model is used by one thread at a time (each point builds its own).
    mutable WindowPiece x_, y_, z_;
    // Both horizontal components enveloped sines under one envelope (the planar case of
    // ch. VI): accel() and accelSlope() sum local Taylor series, a few times cheaper than the
    // closed forms (four transcendental functions) that took half of the solver's time. It
    // memoizes its last patch: a model is used by one thread at a time (each point builds its
    // own).
    mutable std::optional<SinePairSeries> series_;
    double boundRatio_ = 0.0; // with series_: K_y / K_x folded in, sqrt(1 + (K_y/K_x)^2)
    double horizontalBound(double bx, auto&& yBound) const;
    PlanarParams params_;
    // False when |a_z| stays below 1 g over the whole motion: n > 0 throughout, and no window
    // needs its bound (with a vertical record that was a twentieth of a run).
    bool liftPossible_ = false;
    // Bound on |a_h'| over all time (both components enveloped sines; infinite otherwise).
    double slopeBound_ = std::numeric_limits<double>::infinity();
    // With enveloped sines across (and along) the walls: their next cut, asked at cutFrom_, is the
    // answer for every later time up to cutValid_ (a half-period's index, floor(tau / T + 1e-9),
    // is monotone in tau and steps only within 1e-9 T of the cut), so the windows of a record's
    // samples ask the sines once per half-period (issue 34: once per window was 1 % of a run).
    bool sineCuts_ = false;
    mutable double cutFrom_ = NAN, cutEnd_ = NAN, cutValid_ = NAN;
    double horizontalCut(double tau) const;
};

} // namespace kinstab
