// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/risk/HazardCurve.h"

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"

#include <algorithm>
#include <cmath>

namespace kinstab {

namespace {

std::string number(double x) {
    return formatDouble(x);
}

void checkPoint(const std::vector<HazardPoint>& p, std::size_t i,
                const std::function<std::string(std::size_t)>& where) {
    const HazardPoint& q = p[i];
    if (!std::isfinite(q.imG) || !(q.imG > 0.0))
        throw HazardError(where(i) + ": intensity " + number(q.imG) +
                          " g must be a finite number > 0");
    if (q.imG < kMinHazardIntensityG || q.imG > limits::kMaxAmplitudeG)
        throw HazardError(where(i) + ": intensity " + number(q.imG) + " g is outside " +
                          number(kMinHazardIntensityG) + " to " + number(limits::kMaxAmplitudeG) +
                          " g: not an intensity in g");
    if (!std::isfinite(q.annualRate) || !(q.annualRate > 0.0))
        throw HazardError(where(i) + ": annual rate " + number(q.annualRate) +
                          " must be a finite number > 0");
    if (i == 0) return;
    if (!(q.imG > p[i - 1].imG))
        throw HazardError(where(i) + ": intensity " + number(q.imG) +
                          " g does not increase on the previous point's " + number(p[i - 1].imG) +
                          " g");
    if (q.annualRate > p[i - 1].annualRate)
        throw HazardError(where(i) + ": annual rate " + number(q.annualRate) +
                          " increases on the previous point's " + number(p[i - 1].annualRate) +
                          " (the rate of exceeding a larger intensity cannot be larger)");
}

} // namespace

HazardCurve hazardCurve(HazardMeasure measure, std::vector<HazardPoint> points, std::string source,
                        const std::function<std::string(std::size_t)>& where) {
    if (points.size() > limits::kMaxHazardPoints)
        throw HazardError(source + ": " + std::to_string(points.size()) +
                          " points, more than the limit of " +
                          std::to_string(limits::kMaxHazardPoints));
    HazardCurve c;
    c.measure = measure;
    c.source = std::move(source);
    // A zero rate at the top of the table (PoE 0 beyond the largest simulated motion) ends the
    // curve; a zero followed by a positive rate is an increasing rate, refused below.
    std::size_t n = points.size();
    while (n > 0 && points[n - 1].annualRate == 0.0 && std::isfinite(points[n - 1].imG))
        --n;
    c.zeroRatePointsDropped = points.size() - n;
    points.resize(n);
    for (std::size_t i = 0; i < points.size(); ++i)
        checkPoint(points, i, where);
    if (points.size() < 2)
        throw HazardError(c.source + ": " + std::to_string(points.size()) +
                          " point(s) with a positive rate; a hazard curve needs at least 2");
    c.points = std::move(points);
    return c;
}

double hazardRateAt(const HazardCurve& c, double imG) {
    const auto& p = c.points;
    const auto hi = std::upper_bound(p.begin() + 1, p.end() - 1, imG,
                                     [](double x, const HazardPoint& q) { return x < q.imG; });
    const HazardPoint& a = *(hi - 1);
    const HazardPoint& b = *hi;
    const double t = std::log(imG / a.imG) / std::log(b.imG / a.imG);
    return a.annualRate * std::exp(t * std::log(b.annualRate / a.annualRate));
}

} // namespace kinstab
