// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The work an A_crit search of an enveloped sine may cost, bounded before it starts.
//
// The exact solver's cost grows with the sine's half-periods it walks while anything can still
// slip, not with the number of runs alone: a search at 1000 Hz, or under an envelope that decays
// over a quarter of an hour, makes hundreds of runs of tens of thousands of half-periods each.
// Every input may lie in its own range and the combination still run for minutes, so the
// product is bounded as well, and a search beyond it is refused naming its inputs.

#include "core/base/NumberInput.h"
#include "core/slab/PlanarCase.h"
#include "core/slab/Slab1DCase.h"
#include "core/sweep/CriticalAmplitude.h"

namespace kinstab {

// What one run of the model costs against a 1-DOF run of the same sine: the planar slab's
// implicit steps cost about nine (a `kinstab-cli bench` figure; see README, Performance).
struct SineWorkModel {
    double frequencyHz = 1.0;     // the fastest sine of the run (planar: max(f_x, f_y))
    double amplitudeFactor = 1.0; // the largest component over A (planar: max(1, A_y / A_x))
    double costFactor = 1.0;      // per half-period, against the 1-DOF exact solver
};

// Measured with `kinstab-cli bench` on the reference machine: a planar run costs about nine
// 1-DOF runs of the same sine; the paper's RK4 solver costs one exact half-period per eight of
// its steps.
inline constexpr double kPlanarCostFactor = 9.0;
inline constexpr double kPaperStepsPerExactHalfPeriod = 8.0;

// The 1-DOF case's solver against the exact one: the paper's RK4 at its steps per period.
double solverCostFactor(const Slab1DCase& c);

// Upper bound of the half-periods one run at amplitude A walks while A e(t) >= mu, e(t) <=
// exp(-alpha t) (Furgerson 1980, ch. IV), capped by the run's own end tau_out t*.
double sineHalfPeriods(const Slab1DCase& c, double amplitude, const SineWorkModel& m);

// Runs of a search: its scan's points and the halvings of the last step down to the tolerance.
long searchRuns(double scanFrom, const CriticalSearch& s);

// One run's work in half-periods of the 1-DOF exact solver; a run counts at least
// kRunFloorHalfPeriods (what a run costs before its first half-period: setting up, the peak
// searches of the first segment; a 257 x 257 surface point costs about four).
double runWork(const Slab1DCase& c, double amplitude, const SineWorkModel& m);
inline constexpr double kRunFloorHalfPeriods = 5.0;
// About 3.4 µs a half-period on one core of the reference machine (kinstab-cli bench): a run
// or a search at most 10 s, a surface (shown with progress, and cancellable) at most about six
// minutes of one core.
inline constexpr double kMaxSearchWork = 3e6;
inline constexpr double kMaxSurfaceWork = 1e8;

// Nothing when the work fits; else the frequency named, with what the runs would walk and which
// inputs shorten it. A run and a search are held to kMaxSearchWork, a surface (at its largest
// amplitude and frequency) to kMaxSurfaceWork.
InputProblem checkRunWork(const Slab1DCase& c, double amplitude, const SineWorkModel& m);
InputProblem checkSearchWork(const Slab1DCase& c, double scanFrom, const CriticalSearch& s,
                             const SineWorkModel& m);
// The planar model's run: its faster sine, its larger component, its cost factor.
SineWorkModel planarWork(const PlanarCase& c, double fxHz);
InputProblem checkPlanarRunWork(const PlanarCase& c, double ax, double fxHz);
InputProblem checkSurfaceWork(const Slab1DCase& c, std::size_t points, double maxAmplitude,
                              const SineWorkModel& m);

} // namespace kinstab
