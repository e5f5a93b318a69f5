// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A site's seismic hazard curve: the annual rate lambda(x) at which an intensity measure exceeds
// x, at tabulated intensities. Built only through hazardCurve(), which refuses what the risk
// integral cannot use: fewer than two points, values that are not finite, intensities that are
// not positive and increasing, rates that are not positive or that increase with intensity.

#include "core/risk/HazardMeasure.h"

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace kinstab {

// Every problem with a hazard curve or file: "FILE:LINE: what" (or the JSON path for a JSON
// file), so the engineer can find the value.
struct HazardError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Intensities of a hazard curve lie within 1e-6 g (a thousand times below the smallest any hazard
// source tabulates) and limits::kMaxAmplitudeG: beyond, a value is in other units than g. The
// range also keeps every median the risk targets search (ln x -+ 108 beta, beta <= 5) a finite,
// normal double.
inline constexpr double kMinHazardIntensityG = 1e-6;

struct HazardPoint {
    double imG = 0;        // g
    double annualRate = 0; // of exceeding imG, per year
};

struct HazardCurve {
    HazardMeasure measure;
    std::vector<HazardPoint> points; // imG increasing, annualRate > 0 and non-increasing
    std::string source;              // the file, and the site or response picked in it
    std::string format;              // "openquake" | "usgs" | "csv" (core/risk/HazardFile.h)
    // Points at the top of the table with a rate of zero (a PoE written as 0): the curve ends at
    // the last positive rate, because a zero rate has no logarithm to interpolate.
    std::size_t zeroRatePointsDropped = 0;
};

// where(i): the place of points[i] in its file for a message ("hazard.csv:7"). Drops trailing
// zero rates (counted); throws HazardError for anything else the integral cannot use.
HazardCurve hazardCurve(HazardMeasure measure, std::vector<HazardPoint> points, std::string source,
                        const std::function<std::string(std::size_t)>& where);

// lambda(x) interpolated linearly in log-log between the points; x within the curve's range.
double hazardRateAt(const HazardCurve& c, double imG);

} // namespace kinstab
