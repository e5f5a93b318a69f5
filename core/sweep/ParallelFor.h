// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The one thread pool of core: body(k) for k in [0, n) on a few threads, the calling thread
// being one of them. The γc sweep and the A_crit(f) curve both run on it, so a run never holds
// two pools at once.

#include "core/sweep/SweepControl.h"

#include <cstddef>
#include <functional>

namespace kinstab {

// Threads a run of n items uses: `threads` (<= 0: all hardware threads), at least 1, at most n.
int poolThreads(int threads, std::size_t n);

// Indices are handed out in increasing order; a cancel stops handing out new ones. When a body
// throws, no new index is handed out, the bodies running finish, and the exception of the lowest
// failing index is rethrown: the one a plain loop would have met first.
void parallelFor(std::size_t n, int threads, const SweepControl* control,
                 const std::function<void(std::size_t)>& body);

} // namespace kinstab
