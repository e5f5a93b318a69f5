// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/friction/ConfidenceIntervals.h"

#include "core/numerics/ChiSquared.h"
#include "core/numerics/StudentT.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace kinstab {

PercentagePoints percentagePoints(int n, double tail) {
    if (n < 2)
        throw std::invalid_argument("confidence intervals need at least 2 values, got " +
                                    std::to_string(n));
    if (!(tail > 0.0 && tail < 0.5))
        throw std::invalid_argument("tail probability must be in (0, 0.5)");
    const double dof = n - 1.0;
    return {chiSquaredQuantile(1.0 - tail, dof), chiSquaredQuantile(tail, dof),
            studentTQuantile(1.0 - tail, dof)};
}

SampleIntervals sampleIntervals(const std::vector<double>& x, double tail,
                                const PercentagePoints& pts) {
    if (x.size() < 2) throw std::invalid_argument("confidence intervals need at least 2 values");
    SampleIntervals r;
    r.tail = tail;
    r.points = pts;
    r.n = static_cast<int>(x.size());
    for (double v : x)
        r.mean += v / r.n;
    for (double v : x)
        r.variance += (v - r.mean) * (v - r.mean) / (r.n - 1);
    r.sd = std::sqrt(r.variance);
    const double ss = (r.n - 1) * r.variance;
    r.varianceLower = ss / pts.chi2Upper;
    r.varianceUpper = ss / pts.chi2Lower;
    r.sdLower = std::sqrt(r.varianceLower);
    r.sdUpper = std::sqrt(r.varianceUpper);
    const double half = pts.t * r.sd / std::sqrt(static_cast<double>(r.n));
    r.meanLower = r.mean - half;
    r.meanUpper = r.mean + half;
    return r;
}

SampleIntervals sampleIntervals(const std::vector<double>& x, double tail) {
    return sampleIntervals(x, tail, percentagePoints(static_cast<int>(x.size()), tail));
}

} // namespace kinstab
