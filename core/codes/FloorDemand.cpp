// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/codes/FloorDemand.h"

namespace kinstab {

std::vector<double> relativeLevelHeights(const Building& b) {
    std::vector<double> z = levelHeights(b);
    for (double& x : z)
        x /= b.height;
    return z;
}

} // namespace kinstab
