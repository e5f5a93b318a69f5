// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/friction/GrubbsTest.h"

#include "core/base/NameTable.h"

#include "core/numerics/StudentT.h"

#include <cmath>
#include <stdexcept>

namespace kinstab {

double grubbsCritical(int n, double alpha, OutlierSide side) {
    const double a = side == OutlierSide::TwoSided ? alpha / (2.0 * n) : alpha / n;
    const double t = studentTQuantile(1.0 - a, n - 2.0);
    return (n - 1.0) / std::sqrt(static_cast<double>(n)) * std::sqrt(t * t / (n - 2.0 + t * t));
}

GrubbsResult grubbsTest(const std::vector<double>& x, double alpha, OutlierSide side) {
    if (x.size() < 3)
        throw std::invalid_argument("Grubbs test needs at least 3 values, got " +
                                    std::to_string(x.size()));
    if (!(alpha > 0.0 && alpha < 1.0))
        throw std::invalid_argument("Grubbs test: alpha must be in (0, 1)");
    GrubbsResult r;
    r.n = static_cast<int>(x.size());
    r.alpha = alpha;
    r.side = side;
    for (double v : x)
        r.mean += v / r.n;
    double ss = 0.0;
    for (double v : x)
        ss += (v - r.mean) * (v - r.mean);
    r.sd = std::sqrt(ss / (r.n - 1));
    if (!(r.sd > 0.0)) throw std::invalid_argument("Grubbs test: all values are equal");
    double worst = -1.0;
    for (int i = 0; i < r.n; ++i) {
        const double d = side == OutlierSide::Largest    ? x[i] - r.mean
                         : side == OutlierSide::Smallest ? r.mean - x[i]
                                                         : std::abs(x[i] - r.mean);
        if (d > worst) worst = d, r.index = i;
    }
    r.value = x[r.index];
    r.statistic = worst / r.sd;
    r.critical = grubbsCritical(r.n, alpha, side);
    r.rejected = r.statistic > r.critical;
    return r;
}

// OutlierSide's names, in its declaration order (Largest, Smallest, TwoSided).
constexpr std::array<const char*, 3> kOutlierSideNames = {"largest", "smallest", "two-sided"};
static_assert(kOutlierSideNames.size() == static_cast<std::size_t>(OutlierSide::TwoSided) + 1);

const char* outlierSideName(OutlierSide side) {
    return enumName(kOutlierSideNames, side);
}

} // namespace kinstab
