#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "app/cli/ModelFlags.h"
#include "app/cli/PlanarFlags.h"
#include "core/io/ResultJson.h"
#include "core/sweep/CriticalAmplitude.h"

#include <iostream>

namespace kinstab::cli {

int runCritical(const ArgList& argv) {
    std::set<std::string> flags = modelFlagNames();
    flags.insert({"frequencies", "max-amplitude", "scan-step", "tolerance"});
    const Args args(argv, flags);
    const std::vector<double> freqs = args.list("frequencies");
    const std::string e = validateGrid(SweepGrid{{1.0}, freqs});
    if (!e.empty()) throw UsageError("--" + e);
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

    if (isPlanar(args)) return runCriticalPlanar(args, freqs, search);
    const Slab1DCase c = slab1DCaseFromFlags(args);
    const PointFunction point = slab1DPoint(c);
    nlohmann::json crit = nlohmann::json::array();
    for (double f : freqs) {
        const CriticalResult r = criticalAmplitude(point, f, c.slab.mu, search);
        crit.push_back(r.amplitude ? nlohmann::json(*r.amplitude) : nlohmann::json());
    }
    nlohmann::json j = {{"frequencies", freqs},
                        {"a_crit", crit},
                        {"model", "slab1d"},
                        {"solver", solverName(c.solver)},
                        {"envelope", envelopeJson(c)},
                        {"mu", c.slab.mu},
                        {"tstar", c.tstar},
                        {"max_amplitude", search.to},
                        {"scan_step", search.scanStep},
                        {"tolerance", search.tolerance}};
    std::cout << j.dump(2) << "\n";
    return 0;
}

} // namespace kinstab::cli
