// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/risk/RiskIntegrand.h"

#include <algorithm>
#include <cmath>

namespace kinstab {

std::vector<RiskIntegrandPoint> riskIntegrand(const HazardCurve& curve, const CollapseFragility& f,
                                              std::size_t perSegment) {
    const auto& p = curve.points;
    const std::size_t n = std::max<std::size_t>(perSegment, 1);
    std::vector<RiskIntegrandPoint> out;
    out.reserve((p.size() - 1) * (n + 1));
    for (std::size_t i = 0; i + 1 < p.size(); ++i) {
        const double sa = std::log(p[i].imG), sb = std::log(p[i + 1].imG);
        const double k = std::log(p[i].annualRate / p[i + 1].annualRate) / (sb - sa); // >= 0
        for (std::size_t j = 0; j <= n; ++j) {
            const double s = sa + (sb - sa) * static_cast<double>(j) / static_cast<double>(n);
            RiskIntegrandPoint q;
            q.imG = j == n ? p[i + 1].imG : std::exp(s); // the curve's own points exactly
            q.annualRate = p[i].annualRate * std::exp(-k * (s - sa));
            q.pCollapse = collapseProbability(f, q.imG);
            q.density = k * q.annualRate * q.pCollapse;
            out.push_back(q);
        }
    }
    return out;
}

} // namespace kinstab
