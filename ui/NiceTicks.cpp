// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/NiceTicks.h"

#include <algorithm>
#include <cmath>

namespace kinstab::ui {

double niceTickStep(double range, int count) {
    if (!(range > 0) || count < 1) return 1.0;
    const double raw = range / count;
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    const double n = raw / mag;
    return (n < 1.5 ? 1.0 : n < 3.5 ? 2.0 : n < 7.5 ? 5.0 : 10.0) * mag;
}

double niceStep(double lo, double hi, int maxTicks) {
    const double span = std::abs(hi - lo);
    if (!(span > 0) || !std::isfinite(span) || maxTicks < 1) return 1.0;
    double decade = std::pow(10.0, std::floor(std::log10(span / maxTicks)));
    for (int k = 0; k < 4; ++k, decade *= 10) // bounded: one decade up always fits
        for (double m : {1.0, 2.0, 5.0})
            if (span / (m * decade) <= maxTicks + 1e-9) return m * decade;
    return decade;
}

NiceAxis niceAxis(double lo, double hi, int maxTicks) {
    NiceAxis a;
    a.step = niceStep(lo, hi, maxTicks);
    // A small tolerance so 0.6 stays 0.6 and does not become 0.4 through rounding.
    a.min = std::floor(lo / a.step + 1e-9) * a.step;
    a.max = std::ceil(hi / a.step - 1e-9) * a.step;
    if (a.max <= a.min) a.max = a.min + a.step;
    return a;
}

int NiceAxis::segments() const {
    return std::max(1, static_cast<int>(std::lround((max - min) / step)));
}

int NiceAxis::decimals() const {
    return std::clamp(static_cast<int>(std::ceil(-std::log10(step) - 1e-9)), 0, 6);
}

std::vector<double> niceTicks(double lo, double hi, int maxTicks) {
    const double step = niceStep(lo, hi, maxTicks);
    std::vector<double> out;
    const double first = std::ceil(lo / step - 1e-9) * step;
    for (int k = 0; k <= maxTicks + 1; ++k) {
        const double t = first + k * step;
        if (t > hi + 1e-9 * step) break;
        out.push_back(std::abs(t) < 1e-12 * step ? 0.0 : t);
    }
    return out;
}

} // namespace kinstab::ui
