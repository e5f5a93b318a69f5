// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/codes/CodeResult.h"

#include "core/codes/Building.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace kinstab {

std::vector<double> distributedRatios(const std::vector<double>& weights,
                                      const std::vector<double>& heights, double k, double share) {
    double total = 0, sum = 0;
    for (std::size_t i = 0; i < weights.size(); ++i) {
        total += weights[i];
        sum += weights[i] * std::pow(heights[i], k);
    }
    // F_x / w_x = share · W · h_x^k / Σ w_i h_i^k: independent of the unit of weight.
    std::vector<double> r(weights.size());
    for (std::size_t i = 0; i < weights.size(); ++i)
        r[i] = share * total * std::pow(heights[i], k) / sum;
    return r;
}

CodeResult beginCodeResult(const Building& b, const std::string& inputError, const CodeInfo& code) {
    requireValidBuilding(b);
    if (!inputError.empty()) throw InputError(inputError);
    CodeResult r;
    r.code = code.id;
    r.title = code.title;
    return r;
}

TopForceDistribution distributeWithTopForce(const Building& b, double v, double ft) {
    const std::vector<double> w = levelWeights(b);
    TopForceDistribution d{distributedRatios(w, levelHeights(b), 1.0, v - ft), 0.0};
    d.topWithoutFt = d.ratios.back();
    double total = 0;
    for (double x : w)
        total += x;
    d.ratios.back() += ft * total / w.back(); // F_t / w_n = (F_t / W)(W / w_n)
    return d;
}

double distributionExponent(double t) {
    return std::clamp(1.0 + (t - 0.5) / 2.0, 1.0, 2.0);
}

namespace {
void fail(const std::string& field, double x, const std::string& range, const std::string& unit) {
    std::ostringstream s;
    s << field << " = " << x << (unit.empty() ? "" : " " + unit) << ": must be " << range;
    throw InputError(s.str());
}
std::string num(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}
} // namespace

void requireRange(const std::string& field, double x, double lo, double hi,
                  const std::string& unit) {
    if (!std::isfinite(x) || x < lo || x > hi)
        fail(field, x, "between " + num(lo) + " and " + num(hi), unit);
}

void requireAbove(const std::string& field, double x, double lo, double hi,
                  const std::string& unit) {
    if (!std::isfinite(x) || x <= lo || x > hi)
        fail(field, x, "> " + num(lo) + " and at most " + num(hi), unit);
}

void requireIn(const std::string& field, double x, Range r, const std::string& unit) {
    if (r.loOpen)
        requireAbove(field, x, r.lo, r.hi, unit);
    else
        requireRange(field, x, r.lo, r.hi, unit);
}

} // namespace kinstab
