// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One masonry triplet shear test in its post-fracture region (Furgerson 1980, ch. III):
// shear force V (kips) sampled at displacements delta (in) measured from the peak load.

#include <Eigen/Core>

#include <string>
#include <vector>

namespace kinstab {

struct TripletCurve {
    std::string configuration; // e.g. "BJ-F-NG" (bed joint, not grouted)
    double cpPsi = 0.0;        // confining pressure = confining load / bearing area (psi)
    std::string test;          // test number as printed ("7", "unknown", "5(dup)")
    Eigen::VectorXd delta;     // displacement (in), strictly increasing, delta(0) = peak
    Eigen::VectorXd shear;     // total shear force on the triplet (kips)
};

// Empty when the curve can be fitted; otherwise why not (names the curve and the value):
// at least 3 samples, finite, delta strictly increasing, shear > 0, and a post-peak decay
// (some later sample below the first).
std::string validateCurve(const TripletCurve& curve);

// "BJ-F-NG CP 200 test 7": how messages and reports name a curve.
std::string curveLabel(const TripletCurve& curve);

// The composite curve of Furgerson 1980 (ch. III, "the data curves ... are averaged to form a
// composite curve"): the mean shear at each displacement. All runs must share one delta grid;
// the result's test field lists the runs ("30,43,34,36,21,11"). Throws std::invalid_argument.
TripletCurve compositeCurve(const std::vector<TripletCurve>& runs);

} // namespace kinstab
