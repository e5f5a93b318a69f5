// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The whole chapter III procedure on a set of triplet tests (Furgerson 1980):
//  1. group the runs by configuration and confining pressure;
//  2. fit the decay law to every run, and challenge the per-run V_inf with Grubbs' test
//     (the paper did this for BJ-F-NG-200 and dropped run #7);
//  3. average the kept runs into the composite curve and fit it (the paper's Table 2);
//  4. per configuration, tau_inf = V_inf / A_b against CP and mu_inf as its least-squares
//     slope, CP <= 400 psi (Fig. 21).

#include "core/friction/ConfidenceIntervals.h"
#include "core/friction/CoulombSlope.h"
#include "core/friction/DecayFit.h"
#include "core/friction/GrubbsTest.h"
#include "core/friction/TripletCurve.h"

#include <optional>
#include <string>
#include <vector>

namespace kinstab {

struct CalibrationOptions {
    DecayFitOptions fit;                          // alpha = 2 and the V_inf bounds
    std::vector<double> betas = {0.0, 1.0 / 3.0}; // the best of these per curve
    double maxCpPsi = 400.0;                      // 500 psi excluded: spalling, not sliding
    std::optional<double> bearingAreaIn2;         // A_b; without it mu_inf cannot be given
    double outlierAlpha = 0.05;                   // the paper's 95 %
    OutlierSide outlierSide = OutlierSide::TwoSided;
    // Grubbs' G cannot exceed (n-1)/sqrt(n): 1.155 for n = 3 and 1.5 for n = 4, within 0.1 % and
    // 1.3 % of the two-sided 95 % critical values (1.154, 1.481), so with 3 or 4 runs the test
    // "rejects" whenever two V_inf tie (common here: V_inf often sits on its bound, min V, which is
    // printed to 0.1 kip). The paper tested only the 7-run group.
    int outlierMinRuns = 5;
    bool excludeOutliers = true; // drop rejected runs from the composite (as the paper did)
    std::vector<double> intervalTails = {0.01, 0.05, 0.10}; // Table 3c rows
};

struct RunFit {
    TripletCurve curve;
    DecayFit fit;
    bool excluded = false; // rejected by the outlier test and left out of the composite
};

struct GroupCalibration {
    std::string configuration;
    double cpPsi = 0.0;
    std::vector<RunFit> runs;
    std::optional<GrubbsResult> outlier;    // on the per-run V_inf, when there are enough runs
    std::vector<SampleIntervals> intervals; // of the kept runs' V_inf (n >= 3)
    TripletCurve composite;                 // mean of the kept runs
    DecayFit fit;                           // of the composite
};

struct ConfigurationCalibration {
    std::string configuration;
    std::vector<CoulombPoint> points; // composite V_inf per CP (all CP, including excluded ones)
    std::optional<CoulombFit> coulomb;
    std::string coulombError; // why there is no slope (e.g. a single CP)
};

struct FrictionCalibration {
    CalibrationOptions options;
    std::vector<GroupCalibration> groups;
    std::vector<ConfigurationCalibration> configurations;
};

// Throws std::invalid_argument naming the curve when a run cannot be fitted.
FrictionCalibration calibrateFriction(const std::vector<TripletCurve>& runs,
                                      const CalibrationOptions& options = {});

// The runs of one configuration and CP, in input order.
std::vector<TripletCurve> runsOf(const std::vector<TripletCurve>& runs,
                                 const std::string& configuration, double cpPsi);

} // namespace kinstab
