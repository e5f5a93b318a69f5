// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/teaching/TeachingRun.h"

#include "core/base/NameTable.h"

#include "core/base/TextInput.h"
#include "core/slab/History.h"
#include "ui/teaching/PlanarPath.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>

namespace kinstab::ui {

Slab1DCase TeachingParams::toCase() const {
    Slab1DCase c;
    c.envelope = Envelope::fromPreset(envelope);
    c.tstar = tstar();
    c.slab.mu = mu;
    c.slab.limit = limit;
    c.scale = scale;
    return c;
}

// The 1-DOF case and the planar inputs Teaching sets (no vertical motion).
PlanarCase TeachingParams::toPlanarCase() const {
    PlanarInputs own;
    own.theta = theta;
    own.ayRatio = ayRatio;
    own.fyHz = fyHz;
    return PlanarCase(toCase(), own);
}

TeachingParams teachingParamsOf(const Slab1DCase& c, const std::optional<PlanarCase>& planar,
                                double amplitude, double frequencyHz, TeachingParams base,
                                std::string* notShown) {
    base.amplitude = amplitude;
    base.frequencyHz = frequencyHz;
    base.mu = c.slab.mu;
    base.wallWidthM = wallWidthFromTstar(c.tstar);
    base.limit = c.slab.limit;
    base.scale = c.scale;
    std::string missing;
    if (c.envelope.preset)
        base.envelope = *c.envelope.preset;
    else
        missing = "the project's own envelope (alpha, beta): Teaching shows the '" +
                  presetName(base.envelope) + "' preset";
    base.model = planar ? TeachingModel::Planar : TeachingModel::Slab1D;
    if (planar) {
        base.fyHz = planar->fyHz;
        base.ayRatio = planar->ayRatio;
        base.theta = planar->theta;
        if (planar->vertical)
            missing += std::string(missing.empty() ? "" : "; ") +
                       "the vertical motion: Teaching's planar slab has gravity only";
    }
    if (notShown) *notShown = missing;
    return base;
}

double TeachingParams::tstar() const {
    return tstarFromWallWidth(wallWidthM);
}

DisplayState displayStateOf(EventKind k) {
    switch (k) {
    case EventKind::SlipOnset:
        return DisplayState::Slip;
    case EventKind::Stick:
        return DisplayState::Stick;
    case EventKind::Reversal:
        return DisplayState::Reversal;
    case EventKind::Collapse:
        return DisplayState::Collapse;
    case EventKind::Stable:
    case EventKind::DurationCap:
        return DisplayState::Stable;
    case EventKind::LiftOff:
        return DisplayState::LiftOff;
    }
    return DisplayState::Failed;
}

// DisplayState's names, in its declaration order (AtRest, Slip, Stick, Reversal, Collapse, Stable,
// LiftOff, Failed).
constexpr std::array<const char*, 8> kDisplayStateNames = {
    "at rest", "slip", "stick", "reversal", "collapse", "stable", "lift-off", "failed"};
static_assert(kDisplayStateNames.size() == static_cast<std::size_t>(DisplayState::Failed) + 1);

const char* displayStateName(DisplayState s) {
    return enumName(kDisplayStateNames, s);
}

TeachingRun::TeachingRun(const TeachingParams& p) : params_(p) {
    std::string e = validateEnvelopedSine(p.amplitude, p.frequencyHz, 1.0);
    if (e.empty() && !(std::isfinite(p.wallWidthM) && p.wallWidthM > 0.0 && p.wallWidthM < 10.0))
        e = "wall width = " + formatDouble(p.wallWidthM) + " m: must be > 0 and below 10";
    if (e.empty())
        e = p.model == TeachingModel::Planar ? validatePlanarCase(p.toPlanarCase())
                                             : validateCase(p.toCase());
    if (!e.empty()) {
        error_ = e;
        result_.failure = e;
        return;
    }
    tstar_ = p.tstar();
    const auto t0 = std::chrono::steady_clock::now();
    p.model == TeachingModel::Planar ? runPlanar(p) : runSlab1D(p);
    runSeconds_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (result_.outcome == Outcome::Failed) error_ = result_.failure;
    displayEnd_ = std::max(result_.tauEnd, 1.2 * accel_->envelopePeakTau());
    if (result_.outcome == Outcome::Collapsed) displayEnd_ = result_.tauC + kFallTau;
    if (!std::isfinite(displayEnd_) || displayEnd_ <= 0.0) displayEnd_ = 1.0;
    sampleTrace();
}

void TeachingRun::runSlab1D(const TeachingParams& p) {
    const Slab1DCase c = p.toCase();
    tauRef_ = c.tauRef();
    accel_ = std::make_unique<EnvelopedSine>(c.envelope, p.amplitude, p.frequencyHz, c.tstar);
    SlabEventLog events;
    result_ = kinstab::runSlab1D(c, p.amplitude, p.frequencyHz, {}, &events);
    events_ = std::move(events.events);
}

// The planar solver's events and path, in the 1-DOF shapes the view shows: delta is dx (across
// the walls), the slip direction that of the motion across the walls.
void TeachingRun::runPlanar(const TeachingParams& p) {
    const PlanarCase c = p.toPlanarCase();
    tauRef_ = c.tauRef();
    // The product normalization (PlanarCase's default): each component peaks at its amplitude.
    const Slab1DCase& k = c.common;
    accel_ = std::make_unique<EnvelopedSine>(k.envelope, p.amplitude, p.frequencyHz, k.tstar);
    accelY_ = std::make_unique<EnvelopedSine>(k.envelope, p.ayRatio * p.amplitude, p.fyHz, k.tstar);
    PlanarEventLog events;
    PlanarPathLog path;
    PlanarRecorderPair both(&events, &path);
    PlanarResult r = kinstab::runPlanar(c, p.amplitude, p.frequencyHz, &both);
    result_ = std::move(r.slab);
    exitSide_ = r.exitSide;
    path_ = std::move(path.path);
    events_.clear();
    for (const PlanarEvent& e : events.events) {
        // A slip starts from rest against the base acceleration (u' = -a_h at u = 0), so its
        // direction across the walls is that of -a_x; later events carry their own velocity.
        const double ax = accel_->accel(e.tau);
        const bool fromRest = e.kind == EventKind::SlipOnset || e.kind == EventKind::Reversal;
        const int dir = e.kind == EventKind::Stick || e.kind == EventKind::Stable ? 0
                        : fromRest ? (ax < 0) - (ax > 0)
                                   : (e.ux > 0) - (e.ux < 0);
        events_.push_back({e.tau, e.kind, e.dx, e.ux, dir});
    }
}

double TeachingRun::gammaC() const {
    return collapseFactor(tauRef_, result_);
}

std::vector<double> TeachingRun::eventTimes() const {
    std::vector<double> t;
    t.reserve(events_.size());
    for (const SlabEvent& e : events_)
        t.push_back(e.tau);
    return t;
}

TeachingFrame TeachingRun::frameAt(double tau) const {
    TeachingFrame f;
    f.tau = std::clamp(tau, 0.0, displayEnd_);
    if (!accel_) return f;
    const auto& ev = events_;
    const bool collapsed = result_.outcome == Outcome::Collapsed;
    // After collapse the relative motion is frozen at tau_c; only the free end falls.
    const double tRel = collapsed ? std::min(f.tau, result_.tauC) : f.tau;
    const HistorySample s =
        planar() ? planarStateAt(path_, tRel) : stateAt(*accel_, params_.mu, ev, tRel);
    f.accel = accel_->accel(f.tau);
    if (accelY_) {
        const HistorySample y = planarStateAt(path_, tRel, true);
        f.deltaY = y.delta;
        f.accelY = accelY_->accel(f.tau);
        f.baseDispY = accelY_->displacementChange(0.0, f.tau);
    }
    f.envelope = accel_->amplitude() / accel_->sMax() * accel_->envelopeAt(f.tau);
    f.delta = s.delta;
    f.velocity = s.velocity;
    f.direction = s.state;
    f.baseDisp = accel_->displacementChange(0.0, f.tau); // from rest: y_b(0) = y_b'(0) = 0
    const auto it = std::upper_bound(ev.begin(), ev.end(), f.tau,
                                     [](double t, const SlabEvent& e) { return t < e.tau; });
    f.eventIndex = static_cast<int>(it - ev.begin()) - 1;
    f.state = f.eventIndex < 0 ? DisplayState::AtRest : displayStateOf(ev[f.eventIndex].kind);
    if (collapsed && f.tau > result_.tauC) {
        const double h = f.tau - result_.tauC;
        f.fallDrop = 0.5 * h * h; // 1 g in units of d/2 and t*
    }
    return f;
}

void TeachingRun::sampleTrace() {
    // Enough points to resolve every half-period, capped so a long run stays cheap to draw.
    const double halfPeriod = std::numbers::pi / accel_->omega();
    const double step =
        std::max(displayEnd_ / 6000.0, std::min(halfPeriod / 16.0, displayEnd_ / 1500.0));
    std::vector<double> times;
    for (double t = 0.0; t < displayEnd_; t += step)
        times.push_back(t);
    for (const SlabEvent& e : events_)
        times.push_back(e.tau);
    times.push_back(displayEnd_);
    std::sort(times.begin(), times.end());
    times.erase(std::unique(times.begin(), times.end()), times.end());
    trace_.clear();
    trace_.reserve(times.size());
    for (double t : times) {
        const TeachingFrame f = frameAt(t);
        trace_.push_back(
            {t, f.accel, std::hypot(f.accel, f.accelY), f.envelope, f.delta, f.deltaY, f.state});
    }
}

} // namespace kinstab::ui
