// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Wall seconds since a moment, on the steady clock: how every part of a run reports its time.

#include <chrono>

namespace kinstab {

using SteadyClock = std::chrono::steady_clock;

inline double secondsSince(SteadyClock::time_point t0) {
    return std::chrono::duration<double>(SteadyClock::now() - t0).count();
}

} // namespace kinstab
