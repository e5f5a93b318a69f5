// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One 1-DOF run prepared for the Teaching view: the solver's event list, and the exact state at
// any tau rebuilt from it (core/slab/History.h), plus the base motion for the drawing.

#include "core/excitation/EnvelopedSine.h"
#include "core/slab/PlanarCase.h"
#include "core/slab/Slab1DCase.h"

#include <memory>
#include <string>
#include <vector>

namespace kinstab::ui {

// The 1-DOF slab of ch. IV, or the planar 2-DOF slab of ch. VI (gravity only vertically).
enum class TeachingModel { Slab1D, Planar };

// What the user sets in the Teaching view. The wall width fixes t* = sqrt(d / 2g) (docs/theory.md
// §2).
struct TeachingParams {
    EnvelopePreset envelope = EnvelopePreset::Moderate;
    TauScale scale = TauScale::TauMax;
    double amplitude = 1.0;                        // g
    double frequencyHz = 1.0;                      // Hz
    double mu = 0.6;                               // friction coefficient
    double wallWidthM = wallWidthFromTstar(0.099); // m: the paper's "8 inch" wall
    double limit = 1.0;                            // bearing / (d/2)
    TeachingModel model = TeachingModel::Slab1D;
    double fyHz = 1.0;    // planar: frequency along the walls
    double ayRatio = 0.9; // planar: A_y / A_x (the paper's, from Pacoima Dam)
    double theta = 20.0;  // planar: 2 wall length / wall width (the paper's)

    Slab1DCase toCase() const;
    PlanarCase toPlanarCase() const;
    double tstar() const;
    bool operator==(const TeachingParams&) const = default;
};

// The Teaching parameters of one point (A, f) of a project's run: its model (planar when the
// planar case ran), mu, t*, limit, scale, envelope preset and planar inputs; the rest of `base`
// (presentation choices) kept. An envelope that is no preset keeps base's preset, and a planar
// vertical motion is not animated (Teaching's planar slab has gravity only): *notShown says so.
TeachingParams teachingParamsOf(const Slab1DCase& c, const std::optional<PlanarCase>& planar,
                                double amplitude, double frequencyHz, TeachingParams base,
                                std::string* notShown = nullptr);

// The state the drawing shows: the kind of the last event at or before tau.
enum class DisplayState { AtRest, Slip, Stick, Reversal, Collapse, Stable, LiftOff, Failed };
DisplayState displayStateOf(EventKind k);
const char* displayStateName(DisplayState s);

struct TeachingFrame {
    double tau = 0;
    double accel = 0;     // base acceleration, g
    double envelope = 0;  // the bound A e(t* tau) / S_max, g
    double delta = 0;     // relative displacement, d/2
    double velocity = 0;  // relative velocity
    double accelY = 0;    // planar: base acceleration along the walls, g
    double deltaY = 0;    // planar: relative displacement along the walls, d/2
    double baseDispY = 0; // planar: base displacement along the walls, d/2
    double baseDisp = 0;  // absolute base displacement from rest, d/2 (double integral of a)
    double fallDrop = 0;  // after collapse: free-fall drop of the slab's free end, d/2
    int direction = 0;    // slip direction (+1, -1, 0)
    int eventIndex = -1;  // last event at or before tau
    DisplayState state = DisplayState::AtRest;
};

struct TraceSample {
    double tau, accel, accelH, envelope, delta, deltaY; // accelH: |a_h| (planar), |a| (1-DOF)
    DisplayState state;
};

class TeachingRun {
public:
    TeachingRun() : TeachingRun(TeachingParams{}) {}
    explicit TeachingRun(const TeachingParams& p);

    const TeachingParams& params() const { return params_; }
    const SlabResult& result() const { return result_; }
    const std::vector<SlabEvent>& events() const { return events_; }
    bool planar() const { return params_.model == TeachingModel::Planar; }
    ExitSide exitSide() const { return exitSide_; } // planar collapse: across or along the walls
    const std::string& error() const { return error_; } // invalid input, or a failed run
    double tstar() const { return tstar_; }
    double tauRef() const { return tauRef_; }
    double gammaC() const;
    double runSeconds() const { return runSeconds_; } // wall time of the solver call
    // The animation runs over [0, displayEnd]: to the end of the run, at least to 1.2 times
    // the envelope's peak (so that a run that never slips still shows the shaking), and for a
    // collapse a short free fall after tau_c.
    double displayEnd() const { return displayEnd_; }
    TeachingFrame frameAt(double tau) const;
    const std::vector<TraceSample>& trace() const { return trace_; }
    std::vector<double> eventTimes() const;

private:
    void runSlab1D(const TeachingParams& p);
    void runPlanar(const TeachingParams& p);
    void sampleTrace();

    TeachingParams params_;
    std::unique_ptr<EnvelopedSine> accel_;  // across the walls
    std::unique_ptr<EnvelopedSine> accelY_; // planar: along the walls
    std::vector<PlanarSample> path_;        // planar: the solver's path (steps and events)
    ExitSide exitSide_ = ExitSide::None;
    SlabResult result_;
    std::vector<SlabEvent> events_; // the run's; planar: in the 1-DOF shape (runPlanar)
    std::string error_;
    double tstar_ = 0.099;
    double tauRef_ = 1;
    double displayEnd_ = 1;
    double runSeconds_ = 0;
    std::vector<TraceSample> trace_;
};

// Free fall of the unsupported end after collapse lasts this long (tau): 1 g drops it
// tau^2 / 2 in units of d/2, i.e. 4.5 (2.25 d) after 3.
inline constexpr double kFallTau = 3.0;

} // namespace kinstab::ui
