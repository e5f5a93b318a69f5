// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A_crit(f): the smallest amplitude that collapses the slab. gamma_c need not be monotone in A,
// so a bare bisection could land on a later transition: scan finely from below, then refine
// the first stable -> collapsed step by bisection.

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
// are to be checked against it first, as kinstab-cli's --scan-step is); the bisection halves a
// 0.01 g step to 1e-16 g in 47 halvings, so 200 is never reached by a valid tolerance.
inline constexpr long kMaxScanPoints = 1'000'000;
inline constexpr int kMaxHalvings = 200;
// The finest tolerance double precision resolves near maxAmplitude (4 ulps); a finer one is
// taken as this.
double smallestTolerance(double maxAmplitude);

CriticalResult criticalAmplitude(const PointFunction& point, double frequencyHz, double mu,
                                 const CriticalSearch& search = {});

} // namespace kinstab
