// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A study's throughput, measured (issue 34): every case of a loaded study (records read) run on
// one thread and on `threads` threads, the two alternating in one process, the rows thrown away.
// Gives cases per CPU-second on each and the wall-time speed-up of the threads over one.

#include "core/numerics/Timing.h"
#include "core/study/StudySpec.h"

#include <cstddef>

namespace kinstab {

struct StudyBenchmark {
    std::size_t cases = 0;
    int threads = 0;
    TimingStats one, many;       // one thread; `threads` threads
    double perCpuSecondOne = 0;  // cases per CPU-second (median CPU time) on one thread
    double perCpuSecondMany = 0; // the same on `threads` threads
    double speedup = 0;          // one / many: median of the per-repeat wall-time ratios
    bool rowsAgree = true;       // one thread's rows equal to the threads' rows, value by value
};

// s: a study with its records loaded (loadStudyRecords). threads >= 1.
StudyBenchmark benchmarkStudy(const StudySpec& s, int threads, int repeats);

} // namespace kinstab
