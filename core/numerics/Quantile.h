// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The q-quantile of sorted values, linear between order statistics (Hyndman & Fan 1996, type 7:
// the default of R and NumPy), for bootstrap percentiles.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace kinstab {

// sorted: ascending, not empty; 0 <= q <= 1.
inline double quantile(const std::vector<double>& sorted, double q) {
    const double pos = q * static_cast<double>(sorted.size() - 1);
    const auto i = static_cast<std::size_t>(std::floor(pos));
    const std::size_t j = std::min(i + 1, sorted.size() - 1);
    const double w = pos - static_cast<double>(i);
    // An infinite value (an unfitted resample's median) is reached, never interpolated into NaN.
    if (w == 0.0 || sorted[i] == sorted[j]) return sorted[i];
    if (std::isinf(sorted[j])) return sorted[j];
    return sorted[i] + w * (sorted[j] - sorted[i]);
}

} // namespace kinstab
