// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/slab/SegmentCuts.h"

#include <utility>

namespace kinstab {

SegmentCuts segmentCuts(const Excitation1D& a, double mu, double lo, double hi) {
    const Crossings up = a.crossings(mu, lo, hi);
    const Crossings down = mu > 0.0 ? a.crossings(-mu, lo, hi) : Crossings{};
    SegmentCuts c;
    c.cut[c.n++] = {lo, 0};
    for (int i = 0; i < up.n; ++i)
        c.cut[c.n++] = {up.t[static_cast<std::size_t>(i)], 1};
    for (int i = 0; i < down.n; ++i)
        c.cut[c.n++] = {down.t[static_cast<std::size_t>(i)], -1};
    // At most eight crossings: insertion sort (std::sort trips a GCC 12 bounds warning here).
    for (std::size_t i = 2; i < c.n; ++i)
        for (std::size_t j = i; j > 1 && c.cut[j - 1].tau > c.cut[j].tau; --j)
            std::swap(c.cut[j - 1], c.cut[j]);
    c.cut[c.n++] = {hi, 0};
    return c;
}

std::optional<int> crossCut(int state, int kind) {
    if (kind == 0) return state;
    if (state == 0) return kind;
    if (state == kind) return 0;
    return std::nullopt;
}

} // namespace kinstab
