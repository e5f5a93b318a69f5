// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/AnalysisRuns.h"
#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "app/cli/ModelFlags.h"
#include "app/cli/PlanarFlags.h"
#include "app/cli/SearchFlags.h"
#include "core/excitation/FrequencyRange.h"
#include "core/io/JsonText.h"
#include "core/io/ResultJson.h"

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

    if (isPlanar(args)) return runCriticalPlanar(args, freqs, search);
    const Slab1DCase c = slab1DCaseFromFlags(args);
    AnalysisRequest request;
    request.slab = c;
    request.criticalFrequencies = freqs;
    request.criticalSearch = search;
    // Each run is checked before its verdict counts: a collapse with no finite time is an
    // internal error (exit 3), never an A_crit.
    request.requireSoundRuns = true;
    const nlohmann::json crit = criticalCurveJson(request);
    nlohmann::json j = {{"frequencies", freqs},
                        {"a_crit", crit},
                        {"model", modelKindName(ModelKind::Slab1D)},
                        {"solver", solverName(c.solver)},
                        {"envelope", envelopeJson(c)},
                        {"mu", c.slab.mu},
                        {"tstar", c.tstar},
                        {"max_amplitude", search.to},
                        {"scan_step", search.scanStep},
                        {"tolerance", search.tolerance}};
    std::cout << jsonText(j, 2) << "\n";
    return 0;
}

} // namespace kinstab::cli
