// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The smooth envelope of a floor motion (paper Fig. 27): c (exp(-alpha t) - exp(-beta t))
// fitted by least squares to the local peaks of |a(t)| (one per half cycle), which motivates
// the enveloped sine of docs/theory.md §3. alpha and beta in 1/s, t from the record's start.

#include "core/records/Accelerogram.h"

#include <cmath>
#include <vector>

namespace kinstab {

struct EnvelopeFit {
    double alpha = 0; // 1/s
    double beta = 0;  // 1/s, > alpha
    double scale = 0; // c, g
    double rms = 0;   // g, root-mean-square residual at the peaks
    std::size_t peaks = 0;
    double at(double t) const;
    double peakTime() const {
        return std::log(beta / alpha) / (beta - alpha);
    }                                              // s, where e is largest
    double peak() const { return at(peakTime()); } // g
};

struct PeakPoint {
    double time = 0;  // s
    double value = 0; // |a|, g
};

// Local maxima of |a| between sign changes of a: one per half cycle.
std::vector<PeakPoint> halfCyclePeaks(const Accelerogram& motion);
// Throws std::invalid_argument when the motion has fewer than 3 half-cycle peaks. The method:
// docs/theory.md §7.3 (a coarse grid of rate pairs, then damped Newton on the reduced objective).
EnvelopeFit fitEnvelope(const Accelerogram& motion);
// How many fits this process has begun: the tests' observable that a path fits only where its
// output shows or uses the fit (a critical search's runs and a study's record cases do not).
long envelopeFitsBegun();

} // namespace kinstab
