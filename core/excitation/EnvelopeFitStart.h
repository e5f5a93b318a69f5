// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The coarse start of the envelope fit (core/excitation/EnvelopeFit.h, docs/theory.md §7): decay
// rates g_k = g_0 4^k spanning the record, each pair (alpha, beta) = (g_k, g_l), k < l, scored by
// its least-squares SSE at the half-cycle peaks, together with both ends of the curved valley the
// fits lie in: beta -> alpha (c' t exp(-alpha t)) and beta -> infinity (c exp(-alpha t)).

#include "core/excitation/EnvelopeFitObjective.h"

#include <vector>

namespace kinstab {

struct EnvelopeStart {
    double x = 0;   // ln alpha
    double z = 0;   // the objective's second coordinate (r = beta / alpha - 1 = ratioOf(z))
    double sse = 0; // at the grid's point (or at the valley's end it stands for), g^2
};

// The best pair of each rate alpha = g_k where that best is a local minimum over k, best first, at
// most `starts` of them and each within 25 % of the best's SSE (the objective can have more than
// one valley). p: at least one peak at t > 0.
std::vector<EnvelopeStart> envelopeStarts(const FitPeaks& p, std::size_t starts);

} // namespace kinstab
