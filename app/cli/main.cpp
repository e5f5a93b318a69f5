// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-cli: batch work, scripting and automated checks (docs/user-guide.md, "The command line").
// Exit codes: app/cli/ExitCode.h. SIGINT, SIGTERM and SIGHUP remove the temporary file of an
// output being written and end the process with the signal (core/io/SignalCleanup.h).

#include "app/cli/Args.h"
#include "app/cli/Commands.h"
#include "app/cli/HelpText.h"
#include "app/cli/Suggest.h"
#include "core/io/SignalCleanup.h"

#include <iostream>
#include <map>

int main(int argc, char** argv) {
    using namespace kinstab::cli;
    const std::map<std::string, int (*)(const ArgList&)> commands = {
        {"simulate", runSimulate},
        {"surface", runSurface},
        {"critical", runCritical},
        {"bench", runBench},
        {"precision", runPrecision},
        {"record", runRecord},
        {"codes", runCodes},
        {"check", runCheck},
        {"friction", runFriction},
        {"report", runReport},
        {"floors", runFloors},
        {"study", runStudyCommand},
        {"merge", runMerge},
        {"fragility", runFragility},
        {"risk", runRisk},
        {"rocking", runRocking},
        {"rocking-map", runRockingMap},
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
        const std::string near = kinstab::cli::nearest(first, commandNames());
        std::cerr << "kinstab-cli: unknown command '" << first << "'"
                  << (near.empty() ? std::string() : " (did you mean '" + near + "'?)") << "\n"
                  << usageText();
        return 2;
    }
    for (int i = 2; i < argc; ++i) {
        if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
            const std::string help = commandHelpText(first);
            std::cout << (help.empty() ? usageText() : help);
            return 0;
        }
    }
    // Ctrl+C: one line naming the command on stderr, then the signal's own exit status.
    kinstab::removeTemporariesOnSignals(("kinstab-cli " + first).c_str());
    return runCommand(it->second, argv[1], ArgList(argv + 2, argv + argc));
}
