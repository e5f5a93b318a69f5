// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Confidence intervals for the mean, variance and standard deviation of a normal sample
// (Furgerson 1980, Table 3c, for the per-run V_inf of BJ-F-NG-200 without run #7):
//   variance: [(n-1) s^2 / chi2_{1-p}, (n-1) s^2 / chi2_{p}]
//   sd:       square roots of the variance bounds
//   mean:     mean -/+ t_{1-p} s / sqrt(n)
// with chi2 and t the percentage points at n-1 degrees of freedom; Table 3c's "1-99" row is
// p = 0.01 (a two-sided 98 % interval), "5-95" p = 0.05, "10-90" p = 0.10.

#include <vector>

namespace kinstab {

struct PercentagePoints {
    double chi2Upper = 0.0; // chi2 quantile at 1 - p
    double chi2Lower = 0.0; // chi2 quantile at p
    double t = 0.0;         // t quantile at 1 - p
};

struct SampleIntervals {
    double tail = 0.0; // p
    int n = 0;
    double mean = 0.0, variance = 0.0, sd = 0.0;
    double meanLower = 0.0, meanUpper = 0.0;
    double varianceLower = 0.0, varianceUpper = 0.0;
    double sdLower = 0.0, sdUpper = 0.0;
    PercentagePoints points;
};

// The exact percentage points at n-1 DOF (core/numerics/StudentT.h, ChiSquared.h).
PercentagePoints percentagePoints(int n, double tail);

// Intervals from given percentage points (e.g. the rounded ones a paper printed).
SampleIntervals sampleIntervals(const std::vector<double>& values, double tail,
                                const PercentagePoints& points);
// Intervals from the exact points. Needs n >= 2 and 0 < tail < 0.5; throws std::invalid_argument.
SampleIntervals sampleIntervals(const std::vector<double>& values, double tail);

} // namespace kinstab
