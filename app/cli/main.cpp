// kinstab-cli: batch work, scripting and automated checks (SPEC §12).
// Exit codes: 0 success, 2 bad input (message names the flag and value), 1 internal failure.

#include "app/cli/Args.h"
#include "app/cli/Commands.h"

#include <exception>
#include <functional>
#include <iostream>
#include <map>

namespace {

const char* kUsage = R"(usage: kinstab-cli COMMAND [flags]

commands:
  simulate  --amplitude A --frequency F [model flags] [--history FILE.csv] [--events]
  surface   --amplitudes LIST --frequencies LIST [model flags] [--threads N] [--format json|csv|table] [-o FILE]
  critical  --frequencies LIST [model flags] [--max-amplitude A] [--scan-step S]
  precision [-o FILE.csv] [--repeats N] [--no-regularized]
  bench     [--repeats N] [--threads N] [--amplitudes LIST --frequencies LIST] [model flags]
  simulate  --record FILE [--amplitude PEAK_G] [--floor-period T [--damping Z]] [model flags]
  record    --file FILE [--floor-period T [--damping Z]] [--peaks N] [--spectrum-csv FILE]

LIST: comma-separated numbers or start:stop:step.
model flags: --model slab1d --envelope fast|moderate|slow | --alpha X --beta Y
             --tstar S | --wall-width-in D   --mu M  --limit L  --duration TAU
             --scale tau_max|tau_rise|tau_dur|one  --solver exact|paper [--paper-steps N]
record flags: --record-format auto|at2|cosmos|csmip|values|time-accel  --record-dt S
              --record-unit g|m/s2|cm/s2|ft/s2|in/s2  --record-channel N|NAME
)";

} // namespace

int main(int argc, char** argv) {
    using namespace kinstab::cli;
    const std::map<std::string, std::function<int(const ArgList&)>> commands = {
        {"simulate", runSimulate}, {"surface", runSurface},     {"critical", runCritical},
        {"bench", runBench},       {"precision", runPrecision}, {"record", runRecord},
    };
    if (argc < 2 || std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h") {
        std::cout << kUsage;
        return argc < 2 ? 2 : 0;
    }
    const auto it = commands.find(argv[1]);
    if (it == commands.end()) {
        std::cerr << "kinstab-cli: unknown command '" << argv[1] << "'\n" << kUsage;
        return 2;
    }
    try {
        return it->second(ArgList(argv + 2, argv + argc));
    } catch (const UsageError& e) {
        std::cerr << "kinstab-cli " << argv[1] << ": error: " << e.what() << "\n";
        return 2;
    } catch (const std::exception& e) {
        std::cerr << "kinstab-cli " << argv[1] << ": internal error: " << e.what() << "\n";
        return 1;
    }
}
