// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/rocking/Block.h"

#include "core/base/PhysicalConstants.h"

#include <cmath>

namespace kinstab {

double blockAlpha(const Block& b) {
    return std::atan2(b.halfWidth, b.halfHeight);
}

double blockRadius(const Block& b) {
    return std::hypot(b.halfWidth, b.halfHeight);
}

double blockFrequency(const Block& b) {
    return std::sqrt(3.0 * kStandardGravity / (4.0 * blockRadius(b)));
}

double housnerRestitution(double alpha) {
    const double s = std::sin(alpha);
    return 1.0 - 1.5 * s * s;
}

Block blockFromAlphaP(double alpha, double p) {
    const double r = 3.0 * kStandardGravity / (4.0 * p * p);
    return {r * std::sin(alpha), r * std::cos(alpha)};
}

InputProblem checkBlock(const Block& b) {
    if (auto p = checkInput(kHalfWidthInput, b.halfWidth); !p.empty()) return p;
    return checkInput(kHalfHeightInput, b.halfHeight);
}

} // namespace kinstab
