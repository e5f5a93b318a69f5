// SPDX-License-Identifier: GPL-3.0-or-later
#include "report/DecimatedSeries.h"

#include <algorithm>
#include <cmath>

namespace kinstab::report {

QList<QPointF> decimatedSeries(const std::vector<double>& y, double dt, int buckets,
                               bool absolute) {
    QList<QPointF> out;
    const std::size_t n = y.size();
    const std::size_t per =
        std::max<std::size_t>(1, (n + static_cast<std::size_t>(std::max(buckets, 1)) - 1) /
                                     static_cast<std::size_t>(std::max(buckets, 1)));
    const auto value = [&](std::size_t i) { return absolute ? std::abs(y[i]) : y[i]; };
    for (std::size_t b = 0; b < n; b += per) {
        const std::size_t e = std::min(n, b + per);
        std::size_t lo = b, hi = b;
        for (std::size_t i = b; i < e; ++i) {
            if (value(i) < value(lo)) lo = i;
            if (value(i) > value(hi)) hi = i;
        }
        for (std::size_t i : {std::min(lo, hi), std::max(lo, hi)}) {
            out.append(QPointF(dt * static_cast<double>(i), value(i)));
            if (lo == hi) break;
        }
    }
    return out;
}

} // namespace kinstab::report
