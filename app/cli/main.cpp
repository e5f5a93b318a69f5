// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli: batch work, scripting and automated checks (docs/user-guide.md, "The command line").
// Exit codes: 0 success; 2 bad input (the message names the flag and value); 3 no result could be
// delivered: an output could not be written (full disk, full or closed stdout, no permission;
// any file that was there before is left as it was) or a result was not finite or a search reached
// its bound (kinstab::InternalError, "internal error: ..."); 1 any other failure.
// SIGINT, SIGTERM and SIGHUP remove the temporary file of an output being written and end the
// process with the signal (core/io/SignalCleanup.h).

#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "app/cli/HelpText.h"
#include "core/base/InternalError.h"
#include "core/io/AtomicFile.h"
#include "core/io/SignalCleanup.h"

#include <exception>
#include <functional>
#include <iostream>
#include <map>

int main(int argc, char** argv) {
    using namespace kinstab::cli;
    const std::map<std::string, std::function<int(const ArgList&)>> commands = {
        {"simulate", runSimulate}, {"surface", runSurface},     {"critical", runCritical},
        {"bench", runBench},       {"precision", runPrecision}, {"record", runRecord},
        {"codes", runCodes},       {"check", runCheck},         {"friction", runFriction},
        {"report", runReport},     {"floors", runFloors},       {"study", runStudyCommand},
        {"merge", runMerge},       {"fragility", runFragility},
    };
    const std::string first = argc < 2 ? std::string() : argv[1];
    if (argc < 2 || first == "--help" || first == "-h") {
        std::cout << usageText();
        return argc < 2 ? 2 : 0;
    }
    if (first == "--version") {
        std::cout << versionText();
        return 0;
    }
    const auto it = commands.find(first);
    if (it == commands.end()) {
        std::cerr << "kinstab-cli: unknown command '" << first << "'\n" << usageText();
        return 2;
    }
    for (int i = 2; i < argc; ++i) {
        if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
            const std::string help = commandHelpText(first);
            std::cout << (help.empty() ? usageText() : help);
            return 0;
        }
    }
    kinstab::removeTemporariesOnSignals();
    try {
        const int code = it->second(ArgList(argv + 2, argv + argc));
        kinstab::flushStandardOutput(); // a full stdout is a failed run, not a silent loss
        return code;
    } catch (const kinstab::WriteError& e) {
        std::cerr << "kinstab-cli " << argv[1] << ": error: " << e.what() << "\n";
        return 3;
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
