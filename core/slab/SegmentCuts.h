// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One segment of the exact 1-DOF solver's time line cut at every crossing of a = +-mu
// (core/slab/ExactSolver.cpp): on each piece between two cuts the signs of |a| - mu and of
// a -+ mu are fixed, so the slab's slip can only stop (not start or reverse) inside a piece.

#include "core/excitation/Excitation1D.h"

#include <array>
#include <cstddef>
#include <optional>

namespace kinstab {

struct SegmentCut {
    double tau = 0;
    int kind = 0; // +1: a crosses mu, -1: a crosses -mu, 0: segment end
};

// The segment's ends and the crossings between them, increasing.
struct SegmentCuts {
    std::array<SegmentCut, 10> cut{};
    std::size_t n = 0;
};
SegmentCuts segmentCuts(const Excitation1D& a, double mu, double lo, double hi);

// The excess state (the sign of a where |a| > mu, 0 where |a| <= mu) on the other side of a cut,
// the same map both ways; nullopt when the cut does not fit the state (rounding).
std::optional<int> crossCut(int state, int kind);

// The excess state on the first piece. It flips at every cut, so it is evaluated once (by
// excessAt(tau), in the longest piece) and carried back through the cuts; a cut that contradicts
// the carried state (only through rounding) falls back to evaluating it in the piece.
template <class ExcessAt> int firstPieceExcess(const SegmentCuts& c, ExcessAt&& excessAt) {
    std::size_t longest = 0;
    for (std::size_t i = 1; i + 1 < c.n; ++i)
        if (c.cut[i + 1].tau - c.cut[i].tau > c.cut[longest + 1].tau - c.cut[longest].tau)
            longest = i;
    int state = excessAt(0.5 * (c.cut[longest].tau + c.cut[longest + 1].tau));
    for (std::size_t i = longest; i > 0; --i) {
        const auto before = crossCut(state, c.cut[i].kind);
        state = before ? *before : excessAt(0.5 * (c.cut[i - 1].tau + c.cut[i].tau));
    }
    return state;
}

} // namespace kinstab
