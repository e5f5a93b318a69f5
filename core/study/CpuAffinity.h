// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// How many CPUs this process may run on: the size of its affinity mask (sched_getaffinity), which
// is what a Slurm allocation or `taskset` grants - not the machine's core count, which
// std::thread::hardware_concurrency reports and which would oversubscribe a shared node.

namespace kinstab {

unsigned allowedCpuCount(); // at least 1

} // namespace kinstab
