// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/CpuAffinity.h"

#include <sched.h>

#include <thread>

namespace kinstab {

unsigned allowedCpuCount() {
    cpu_set_t set;
    CPU_ZERO(&set);
    if (sched_getaffinity(0, sizeof set, &set) == 0) {
        const int n = CPU_COUNT(&set);
        if (n > 0) return static_cast<unsigned>(n);
    }
    // No mask to read (not Linux, or more CPUs than cpu_set_t holds): the core count, at least 1.
    const unsigned h = std::thread::hardware_concurrency();
    return h > 0 ? h : 1;
}

} // namespace kinstab
