// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The floor filter (paper's eq. 6; docs/theory.md §7): the absolute acceleration of a damped linear
// single-degree-of-freedom oscillator (period T, damping ratio zeta) whose base moves with the
// ground record,  x'' + 2 zeta w x' + w^2 x = -a_g(t),  floor = x'' + a_g = -(2 zeta w x' + w^2 x).
// The ground record is linear between samples, so the step from sample to sample is exact
// (Nigam & Jennings 1969, "Calculation of response spectra from strong-motion earthquake
// records", BSSA 59(2)): a 2x2 recurrence whose coefficients depend only on T, zeta and dt.

#include "core/base/NumberInput.h"
#include "core/records/Accelerogram.h"

#include <optional>
#include <string>
#include <vector>

namespace kinstab {

// Range of the oscillator's period, s, for every reader of a floor filter (CLI, project and study
// files, Python). The stiffest buildings have periods near 0.05 s (UBC's T = 0.05 h_n/sqrt(D)
// gives 0.05 s for one storey 10 ft tall and 100 ft long); at 0.01 s (100 Hz) the oscillator is
// rigid at every frequency an accelerograph records (records are filtered below about 50 Hz), so
// a shorter period is a unit slip (ms for s), and far shorter ones (1e-300 s) overflow the
// recurrence into NaN samples. 1000 s is far beyond any building.
inline constexpr double kMinFloorPeriodS = 0.01;
inline constexpr double kMaxFloorPeriodS = 1000.0;

struct FloorFilterParams {
    double period = 1.0;   // s, the building's fundamental period
    double damping = 0.02; // fraction of critical; the paper's 2 %
    // Seconds of free vibration appended after the ground record ends (the floor keeps ringing).
    // None: until the free vibration has decayed to 1 % (ln 100 / (zeta w)), at most 120 s.
    std::optional<double> tail;
};

// Empty when fine; else "floor period 1e-300 s: must be at least 0.01 s and at most 1000 s" (the
// message starts "floor period", "damping" or "tail", which callers use to name their input).
// The first parameter out of range, keyed period_s, damping or tail_s (each front end names
// its own field from the key), with validateFloorFilter's words as its why; or nothing.
InputProblem checkFloorFilter(const FloorFilterParams& p);
std::string validateFloorFilter(const FloorFilterParams& p); // checkFloorFilter's why
double floorTailSeconds(const FloorFilterParams& p);         // the tail actually appended

struct OscillatorState {
    double x = 0; // relative displacement, g s^2
    double v = 0; // relative velocity, g s
};

// Absolute accelerations at the sample times of the ground samples (g), starting from `start`.
std::vector<double> floorAcceleration(const std::vector<double>& ground, double dt, double period,
                                      double damping, OscillatorState start = {});

// The floor motion of a ground record, with the free-vibration tail; metadata names the filter.
Accelerogram floorMotion(const Accelerogram& ground, const FloorFilterParams& p);

} // namespace kinstab
