// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/AnalysisRuns.h"
#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "app/cli/ModelFlags.h"
#include "app/cli/SearchFlags.h"
#include "core/excitation/FrequencyRange.h"
#include "core/io/AnalysisJson.h"
#include "core/io/JsonText.h"

#include <iostream>

namespace kinstab::cli {

int runCritical(const ArgList& argv) {
    std::set<std::string> flags = modelFlagNames();
    flags.insert("frequencies");
    const std::set<std::string> searchFlags = searchFlagNames();
    flags.insert(searchFlags.begin(), searchFlags.end());
    const Args args(argv, flags);
    const std::vector<double> freqs = args.list("frequencies");
    // validateGrid checks each frequency against kFrequencyInput, the count against the limit.
    const std::string e = validateGrid(SweepGrid{{1.0}, freqs});
    if (!e.empty()) throw UsageError("--" + e);
    const CriticalSearch search = criticalSearchFromFlags(args);

    // One path for both models. The planar scan starts where anything can slip at all:
    // A_x sqrt(1 + ratio^2) = mu min n, below mu itself (both components push).
    AnalysisRequest request = modelRequestFromFlags(args);
    request.criticalFrequencies = freqs;
    request.criticalSearch = search;
    // Each 1-DOF run is checked before its verdict counts: a collapse with no finite time is an
    // internal error (exit 3), never an A_crit.
    request.requireSoundRuns = true;
    std::cout << jsonText(criticalCurveJson(request, criticalCurveOf(request)), 2) << "\n";
    return 0;
}

} // namespace kinstab::cli
