#include "app/cli/SearchFlags.h"

namespace kinstab::cli {

std::set<std::string> searchFlagNames() {
    return {"max-amplitude", "scan-step", "tolerance"};
}

CriticalSearch criticalSearchFromFlags(const Args& args) {
    CriticalSearch search;
    search.to = args.number("max-amplitude", 5.0);
    search.scanStep = args.number("scan-step", 0.01);
    search.tolerance = args.number("tolerance", 1e-6);
    if (search.to <= 0.0 || search.to > 1000.0)
        throw UsageError("--max-amplitude " + args.text("max-amplitude") +
                         ": must be > 0 and at most 1000");
    if (search.scanStep <= 0.0 || search.scanStep > search.to)
        throw UsageError("--scan-step " + args.text("scan-step") +
                         ": must be > 0 and below --max-amplitude");
    if (search.tolerance <= 0.0 || search.tolerance > search.scanStep)
        throw UsageError("--tolerance " + args.text("tolerance") +
                         ": must be > 0 and at most --scan-step");
    return search;
}

} // namespace kinstab::cli
