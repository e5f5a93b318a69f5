// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/StudyBenchmark.h"

#include "core/study/StudyRunner.h"

#include <algorithm>
#include <vector>

namespace kinstab {

StudyBenchmark benchmarkStudy(const StudySpec& s, int threads, int repeats) {
    StudyBenchmark b;
    b.threads = std::max(1, threads);
    std::vector<StudyRow> rowsOne, rowsMany;
    const auto pass = [&s](unsigned n, std::vector<StudyRow>& rows) {
        StudyRunOptions o;
        o.threads = n;
        rows = runStudyRows(s, o);
    };
    const PairedTiming t =
        timePaired([&] { pass(1, rowsOne); },
                   [&] { pass(static_cast<unsigned>(b.threads), rowsMany); }, repeats);
    b.cases = studyCaseCount(s);
    b.one = t.first;
    b.many = t.second;
    const auto perCpu = [&b](const TimingStats& x) {
        return x.medianCpuSeconds > 0.0 ? static_cast<double>(b.cases) / x.medianCpuSeconds : 0.0;
    };
    b.perCpuSecondOne = perCpu(b.one);
    b.perCpuSecondMany = perCpu(b.many);
    b.speedup = t.ratioWall;
    b.rowsAgree = rowsOne == rowsMany;
    return b;
}

} // namespace kinstab
