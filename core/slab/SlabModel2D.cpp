// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/slab/SlabModel2D.h"

#include "core/base/NextAfter.h"
#include "core/slab/SlabInputs.h"
#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace kinstab {

InputProblem checkPlanarParams(const PlanarParams& p) {
    if (InputProblem e = checkSlabParams(p); !e.empty()) return e;
    return checkInput(kThetaInput, p.theta);
}

std::string validatePlanarParams(const PlanarParams& p) {
    return describe(checkPlanarParams(p));
}

namespace {
// |a'| <= (A / S_max) (|e'| + omega e) with e = e^{-p tau} - e^{-q tau} <= 1 and
// |e'| = |-p e^{-p tau} + q e^{-q tau}| <= max(p, q) (two terms of opposite signs).
double slopeBound(const EnvelopedSine& c) {
    return c.scale() * (std::max(c.decayP(), c.decayQ()) + c.omega());
}
} // namespace

SlabModel2D::SlabModel2D(std::shared_ptr<const Excitation1D> ax,
                         std::shared_ptr<const Excitation1D> ay,
                         std::shared_ptr<const Excitation1D> az, PlanarParams params)
    : ax_(std::move(ax)), ay_(std::move(ay)), az_(std::move(az)), params_(params),
      liftPossible_(az_ && !(az_->boundAfter(0.0) < 1.0)) {
    const auto* x = dynamic_cast<const EnvelopedSine*>(ax_.get());
    const auto* y = dynamic_cast<const EnvelopedSine*>(ay_.get());
    sineCuts_ = x && (y || !ay_);
    if (sineCuts_) slopeBound_ = std::hypot(slopeBound(*x), y ? slopeBound(*y) : 0.0);
    if (!x || !y) return;
    // One envelope when e_x and e_y agree to the bit over the motion (they are the same two
    // exponentials then); any other pair keeps the general path.
    for (double tau : {0.1, 1.0, 7.3, 31.0, 200.0})
        if (x->envelopeAt(tau) != y->envelopeAt(tau)) return;
    series_.emplace(*x, *y);
    if (x->scale() > 0.0) boundRatio_ = std::hypot(1.0, y->scale() / x->scale());
}

// sqrt(bx^2 + by^2) of the components' bounds; under one envelope the y bound is a fixed
// multiple of the x bound, so the envelope is evaluated once (per window it was a twentieth of a
// run with a vertical record).
double SlabModel2D::horizontalBound(double bx, auto&& yBound) const {
    if (boundRatio_ > 0.0) return bx * boundRatio_;
    return std::hypot(bx, ay_ ? yBound() : 0.0);
}

Vec2 SlabModel2D::accelSlope(double tau) const {
    if (series_) {
        const auto s = series_->slope(tau);
        return {s[0], s[1]};
    }
    return {x_.slope(*ax_, tau), ay_ ? y_.slope(*ay_, tau) : 0.0};
}
double SlabModel2D::normalSlope(double tau) const {
    return az_ ? z_.slope(*az_, tau) : 0.0;
}

void SlabModel2D::WindowPiece::enter(const Excitation1D* a, double l, double h) {
    lo = hi = 0.0;
    windowEnd = start = NAN;
    endKnown = false;
    if (!a) return;
    // The whole window first, then without the double at either end that reads another piece.
    const double next = nextAfter(l, h), last = nextAfter(h, l);
    const std::array<std::array<double, 2>, 4> spans{{{l, h}, {l, last}, {next, h}, {next, last}}};
    for (const auto& [from, to] : spans) {
        if (!a->linearOn(from, to, piece)) continue;
        lo = from;
        hi = to;
        windowEnd = h;
        if (from == l) return;
        start = l;
        startAccel = a->accel(l);
        startSlope = piece.slope; // the window's side: a scan of [l, h) needs the slope into it
        return;
    }
}

void SlabModel2D::enterWindow(double lo, double hi) const {
    if (!series_) {
        x_.enter(ax_.get(), lo, hi);
        y_.enter(ay_.get(), lo, hi);
    }
    z_.enter(az_.get(), lo, hi);
}

double SlabModel2D::onsetMargin(double tau) const {
    const Vec2 a = accel(tau);
    return norm2(a.x, a.y) - params_.mu * normal(tau);
}

double SlabModel2D::onsetMarginSlope(double tau) const {
    Vec2 a, s;
    accelAndSlope(tau, a, s);
    const double m = norm2(a.x, a.y);
    const double dm = m > 0.0 ? (a.x * s.x + a.y * s.y) / m : norm2(s.x, s.y);
    return dm - params_.mu * normalSlope(tau);
}

void SlabModel2D::onsetMarginAndSlope(double tau, double& g, double& slope) const {
    Vec2 a, s;
    accelAndSlope(tau, a, s);
    const double m = norm2(a.x, a.y);
    const double dm = m > 0.0 ? (a.x * s.x + a.y * s.y) / m : norm2(s.x, s.y);
    g = m - params_.mu * normal(tau);
    slope = dm - params_.mu * normalSlope(tau);
}

bool SlabModel2D::quietAfter(double tau) const {
    const double b = horizontalBound(ax_->boundAfter(tau), [&] { return ay_->boundAfter(tau); });
    const double nMin = 1.0 - (az_ ? az_->boundAfter(tau) : 0.0);
    return b < params_.mu * nMin;
}

bool SlabModel2D::quietOn(double lo, double hi) const {
    const double nMin = 1.0 - (az_ ? az_->boundOn(lo, hi) : 0.0);
    // Short windows (a vertical record cuts the time line at every sample): within (hi - lo) / 2
    // of the middle |a_h| moves by at most that times the slope bound. The factor keeps rounding
    // on the safe side. Asked first where it can hold (reach below mu n_min), as it is cheaper
    // than the components' envelope bounds (a twentieth of a run with RSN68 UP); either bound
    // suffices, so the answer is the same in either order.
    const double reach = 0.5 * (hi - lo) * slopeBound_; // infinite or NaN: no slope bound
    if (reach < params_.mu * nMin) {
        const Vec2 a = accel(0.5 * (lo + hi));
        if ((norm2(a.x, a.y) + reach) * (1.0 + 1e-12) < params_.mu * nMin) return true;
    }
    const double b = horizontalBound(ax_->boundOn(lo, hi), [&] { return ay_->boundOn(lo, hi); });
    return b <= params_.mu * nMin;
}

// Each sine's cut e = (k + 1) T is its answer for every tau from where it was asked to e (1 - 2e-9)
// (see sineCuts_); 4e-9 below the nearer cut keeps the rounding of the bound on the safe side.
double SlabModel2D::horizontalCut(double tau) const {
    if (sineCuts_ && tau >= cutFrom_ && tau <= cutValid_) return cutEnd_;
    double end = ax_->segmentEnd(tau);
    if (ay_) end = std::min(end, ay_->segmentEnd(tau));
    if (sineCuts_) {
        cutFrom_ = tau;
        cutEnd_ = end;
        cutValid_ = end - 4e-9 * std::abs(end);
    }
    return end;
}

double SlabModel2D::segmentEnd(double tau) const {
    const double end = horizontalCut(tau);
    return az_ ? std::min(end, az_->segmentEnd(tau)) : end;
}

double SlabModel2D::horizontalTimeScale() const {
    double end = ax_->segmentEnd(0.0);
    if (ay_) end = std::min(end, ay_->segmentEnd(0.0));
    return end;
}

} // namespace kinstab
