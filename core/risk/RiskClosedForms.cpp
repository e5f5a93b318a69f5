// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/risk/RiskClosedForms.h"

#include "core/base/TextInput.h"

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <vector>

namespace kinstab {

namespace {

std::string outsideCurve(const HazardCurve& c, const CollapseFragility& f) {
    if (f.medianG >= c.points.front().imG && f.medianG <= c.points.back().imG) return {};
    return "the median " + formatDouble(f.medianG) + " g lies outside the hazard curve's " +
           formatDouble(c.points.front().imG) + " to " + formatDouble(c.points.back().imG) +
           " g: a local fit there is an extrapolation";
}

// The indices of the points within 2 beta of sc in ln x, and at least the 3 nearest it.
std::vector<std::size_t> fitWindow(const HazardCurve& c, double sc, double beta) {
    std::vector<std::size_t> order(c.points.size());
    for (std::size_t i = 0; i < order.size(); ++i)
        order[i] = i;
    const auto distance = [&](std::size_t i) { return std::abs(std::log(c.points[i].imG) - sc); };
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return distance(a) < distance(b); });
    std::size_t n = 3;
    while (n < order.size() && distance(order[n]) <= 2.0 * beta)
        ++n;
    order.resize(n);
    std::sort(order.begin(), order.end());
    return order;
}

} // namespace

double firstOrderRiskRate(double k0, double k, const CollapseFragility& f) {
    return k0 * std::pow(f.medianG, -k) * std::exp(0.5 * k * k * f.beta * f.beta);
}

std::optional<double> secondOrderRiskRate(double k0, double k1, double k2,
                                          const CollapseFragility& f) {
    const double q = 1.0 / (1.0 + 2.0 * k2 * f.beta * f.beta);
    if (!(q > 0.0) || !std::isfinite(q)) return std::nullopt;
    const double s = std::log(f.medianG);
    const double lnHazard = std::log(k0) - k2 * s * s - k1 * s; // ln lambda(theta)
    return std::exp(0.5 * std::log(q) + (1.0 - q) * std::log(k0) + q * lnHazard +
                    0.5 * q * k1 * k1 * f.beta * f.beta);
}

FirstOrderForm firstOrderForm(const HazardCurve& c, const CollapseFragility& f) {
    FirstOrderForm r;
    r.why = outsideCurve(c, f);
    if (!r.why.empty()) return r;
    r.fitLoG = std::max(c.points.front().imG, f.medianG * std::exp(-f.beta));
    r.fitHiG = std::min(c.points.back().imG, f.medianG * std::exp(f.beta));
    r.k = -std::log(hazardRateAt(c, r.fitHiG) / hazardRateAt(c, r.fitLoG)) /
          std::log(r.fitHiG / r.fitLoG);
    r.lambdaAtMedian = hazardRateAt(c, f.medianG);
    r.k0 = r.lambdaAtMedian * std::pow(f.medianG, r.k);
    r.lambdaC = r.lambdaAtMedian * std::exp(0.5 * r.k * r.k * f.beta * f.beta);
    if (!std::isfinite(r.k0) || !std::isfinite(r.lambdaC))
        r.why = "with the local slope k = " + formatDouble(r.k) + " and beta " +
                formatDouble(f.beta) + " the form overflows double precision";
    return r;
}

// The fit is made in t = ln x - sc (centred, so the normal equations of the QR stay well
// conditioned) and turned back into k0, k1, k2 in ln x; the closed form is invariant under the
// shift, so it is evaluated in t: ln lambda = a0 + a1 t + a2 t^2 gives k0 = e^a0, k1 = -a1,
// k2 = -a2 there.
SecondOrderForm secondOrderForm(const HazardCurve& c, const CollapseFragility& f) {
    SecondOrderForm r;
    r.why = outsideCurve(c, f);
    if (r.why.empty() && c.points.size() < 3)
        r.why = "a quadratic fit needs 3 points, the curve has 2";
    if (!r.why.empty()) return r;
    const FirstOrderForm first = firstOrderForm(c, f);
    const double sc = std::log(f.medianG) - first.k * f.beta * f.beta;
    const std::vector<std::size_t> window = fitWindow(c, sc, f.beta);
    Eigen::MatrixXd a(Eigen::Index(window.size()), 3);
    Eigen::VectorXd y(Eigen::Index(window.size()));
    for (std::size_t j = 0; j < window.size(); ++j) {
        const double t = std::log(c.points[window[j]].imG) - sc;
        a.row(Eigen::Index(j)) << 1.0, t, t * t;
        y(Eigen::Index(j)) = std::log(c.points[window[j]].annualRate);
    }
    const Eigen::Vector3d p = a.colPivHouseholderQr().solve(y);
    r.points = window.size();
    r.fitLoG = c.points[window.front()].imG;
    r.fitHiG = c.points[window.back()].imG;
    r.k2 = -p(2);
    r.k1 = -(p(1) - 2.0 * p(2) * sc);
    r.k0 = std::exp(p(0) - p(1) * sc + p(2) * sc * sc);
    const CollapseFragility shifted{f.medianG * std::exp(-sc), f.beta};
    const std::optional<double> rate = secondOrderRiskRate(std::exp(p(0)), -p(1), -p(2), shifted);
    if (!rate) {
        r.why = "the fitted curvature k2 = " + formatDouble(r.k2) + " with beta " +
                formatDouble(f.beta) + " makes 1 + 2 k2 beta^2 <= 0: the integral diverges";
        return r;
    }
    r.lambdaC = *rate;
    if (!std::isfinite(r.k0) || !std::isfinite(r.lambdaC))
        r.why = "the fitted k0, k1, k2 (a curve far from second order) overflow double precision";
    return r;
}

} // namespace kinstab
