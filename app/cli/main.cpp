// kinstab-cli: batch work, scripting and automated checks (SPEC §12).
// Exit codes: 0 success, 2 bad input (message names the flag and value), 3 a result that is not
// finite or a search that reached its bound (kinstab::InternalError), 1 any other failure.

#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "core/numerics/InternalError.h"
#include "core/numerics/VectorState.h"

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
  codes     --project FILE | building flags + code flags
  check     --project FILE
  friction  --data FILE.csv [--bearing-area IN2] [--alpha 0|2] [--beta best|0|1/3] [--max-cp PSI]
            [--outlier-alpha A] [--outlier-min-runs N] [--keep-outliers] [-o FILE]
  report    --project FILE -o FILE.pdf [--page a4|letter] [--figure-grid N]

LIST: comma-separated numbers or start:stop:step.
model flags: --model slab1d --envelope fast|moderate|slow | --alpha X --beta Y
             --tstar S | --wall-width-in D   --mu M  --limit L  --duration TAU
             --scale tau_max|tau_rise|tau_dur|one  --solver exact|paper [--paper-steps N]
record flags: --record-format auto|at2|cosmos|csmip|values|time-accel  --record-dt S
              --record-unit g|m/s2|cm/s2|ft/s2|in/s2  --record-channel N|NAME
building flags: --stories N --height-ft H|--height-m H --dimension-ft D|--dimension-m D [--period T]
             [--system dual_frame_wall|steel_moment_frame|concrete_moment_frame|steel_eccentric_braced|
              shear_wall|braced_frame|other] [--occupancy standard|assembly|hazardous|essential]
             [--weights LIST] [--story-heights LIST]   (period: each code's formula when absent)
code flags:  UBC 1976  --zone 0-4 --k-factor K [--importance I] [--site-period TS]
             ATC 3-06  --av AV --aa AA | --map-area 1-7; --soil S1|S2|S3 --r R
             UBC 1997  --ubc97-zone 1|2A|2B|3|4 --ubc97-r R [--ubc97-soil SA..SE] [--na --nv] [--ubc97-importance I]
             ASCE 7-22 --sds S --sd1 S --tl T --asce-r R [--s1 S] [--site-class C] [--risk-category 1-4] [--ie I]
             EC8       --ag AGR --ground A-E --q Q [--spectrum-type 1|2] [--importance-class 1-4]
                       [--gamma-i G] [--beta B] [--irregular]
)";

} // namespace

int main(int argc, char** argv) {
    kinstab::clearUpperVectorState(); // see core/numerics/VectorState.h
    using namespace kinstab::cli;
    const std::map<std::string, std::function<int(const ArgList&)>> commands = {
        {"simulate", runSimulate}, {"surface", runSurface},     {"critical", runCritical},
        {"bench", runBench},       {"precision", runPrecision}, {"record", runRecord},
        {"codes", runCodes},       {"check", runCheck},         {"friction", runFriction},
        {"report", runReport},
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
    } catch (const kinstab::InternalError& e) {
        std::cerr << "kinstab-cli " << argv[1] << ": internal error: " << e.what() << "\n";
        return 3;
    } catch (const std::exception& e) {
        std::cerr << "kinstab-cli " << argv[1] << ": internal error: " << e.what() << "\n";
        return 1;
    }
}
