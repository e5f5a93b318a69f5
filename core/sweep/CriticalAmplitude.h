// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A_crit(f): the smallest amplitude that collapses the slab. gamma_c need not be monotone in A,
// so a bare bisection could land on a later transition: scan finely from below, then refine
// the first stable -> collapsed step by bisection.

#include "core/base/InputLimits.h"
#include "core/base/NumberInput.h"
#include "core/sweep/Sweep.h"

#include <optional>

namespace kinstab {

struct CriticalSearch {
    double from = 0.0; // start of the scan (the default starts at mu: below it nothing slips)
    double to = 5.0;   // search limit, g
    double scanStep = 0.01;
    double tolerance = 1e-6;
};

struct CriticalResult {
    std::optional<double> amplitude; // nullopt when nothing up to `to` collapses
    long runs = 0;
};

// Bounds of the search: a scan of more points than this is refused (an InternalError: inputs
// are checked against it first, by checkCriticalSearch); the bisection halves a 0.01 g step to
// 1e-16 g in 47 halvings, so 200 is never reached by a valid tolerance. A hundred thousand
// runs take about 30 s for one frequency of a slab that never falls (0.3 ms a run): the most
// one accepted search may cost (the default, 5 g in 0.01 g steps, is 500).
inline constexpr long kMaxScanPoints = 100'000;
inline constexpr int kMaxHalvings = 200;
// The finest tolerance double precision resolves near maxAmplitude (4 ulps); a finer one is
// taken as this.
double smallestTolerance(double maxAmplitude);

// The search's inputs, declared once for the project, study, command line, Python and GUI.
// The search ends at least at 0.01 g (no slab falls below it: A_crit >= μ >= 0.01) and at most
// at limits::kMaxAmplitudeG.
inline constexpr NumberInput kMaxAmplitudeInput{
    "max_amplitude", "g", {0.01, limits::kMaxAmplitudeG}, 5.0, "largest amplitude searched"};
inline constexpr NumberInput kScanStepInput{
    "scan_step", "g", {0.0, limits::kMaxAmplitudeG, true}, 0.01, "scan step"};
inline constexpr NumberInput kToleranceInput{
    "tolerance", "g", {0.0, limits::kMaxAmplitudeG, true}, 1e-6, "bisection tolerance"};
inline constexpr NumberInput kSearchFromInput{
    "from", "g", {0.0, limits::kMaxAmplitudeG}, 0.0, "start of the scan"};

// The first input of a search out of its range or its relation to the others (the scan step
// within the searched range and at most kMaxScanPoints of them, the tolerance at most the step
// and no finer than double precision resolves), named by its key; or nothing.
InputProblem checkCriticalSearch(const CriticalSearch& s);

// scanFrom: the amplitude below which nothing slips (μ for the 1-DOF slab, ModelPoint::scanFrom
// for any model); the scan starts at the larger of it and search.from.
CriticalResult criticalAmplitude(const PointFunction& point, double frequencyHz, double scanFrom,
                                 const CriticalSearch& search = {});

} // namespace kinstab
