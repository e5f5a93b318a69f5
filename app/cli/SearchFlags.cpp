// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/SearchFlags.h"

#include <string>

namespace kinstab::cli {

std::set<std::string> searchFlagNames() {
    return {"max-amplitude", "scan-step", "tolerance"};
}

CriticalSearch criticalSearchFromFlags(const Args& args) {
    CriticalSearch search;
    search.to = args.input(kMaxAmplitudeInput);
    search.scanStep = args.input(kScanStepInput);
    search.tolerance = args.input(kToleranceInput);
    args.refuse(checkCriticalSearch(search));
    return search;
}

} // namespace kinstab::cli
