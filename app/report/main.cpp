// SPDX-License-Identifier: GPL-3.0-or-later
// kinstab-report: `kinstab-cli report` (app/cli/ReportCommand.cpp), in its own executable so that
// only the report loads Qt Gui; kinstab-cli report runs it (app/cli/ReportLauncher.cpp), and its
// messages speak as kinstab-cli report. Exit codes: app/cli/ExitCode.h.

#include "app/cli/Commands.h"
#include "core/io/SignalCleanup.h"

int main(int argc, char** argv) {
    kinstab::removeTemporariesOnSignals();
    return kinstab::cli::runCommand(kinstab::cli::writeReport, "report",
                                    kinstab::cli::ArgList(argv + 1, argv + argc));
}
