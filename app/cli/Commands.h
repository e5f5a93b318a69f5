// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One function per kinstab-cli subcommand. Each returns the exit code; a UsageError thrown
// from one becomes exit 2 in main.

#include <string>
#include <vector>

namespace kinstab::cli {

using ArgList = std::vector<std::string>;

int runSimulate(const ArgList& args);
int runSurface(const ArgList& args);
int runCritical(const ArgList& args);
int runBench(const ArgList& args);
int runPrecision(const ArgList& args);
int runCodes(const ArgList& args);
int runCheck(const ArgList& args);
// report: runs kinstab-report (ReportLauncher.cpp), the one part of the CLI that needs Qt Gui,
// so that the other commands start without loading Qt (issue 34).
int runReport(const ArgList& args);
// The report itself (ReportCommand.cpp), linked into kinstab-report only.
int writeReport(const ArgList& args);
int runRecord(const ArgList& args);
int runFriction(const ArgList& args);
int runFloors(const ArgList& args);
int runStudyCommand(const ArgList& args); // study (StudyCommand.cpp)
int runMerge(const ArgList& args);
int runFragility(const ArgList& args);
int runRisk(const ArgList& args);
int runRocking(const ArgList& args);    // rocking (RockingCommand.cpp)
int runRockingMap(const ArgList& args); // rocking-map (RockingMapCommand.cpp)

class Args;
// simulate --record FILE (SimulateRecord.cpp), called by runSimulate.
int runSimulateRecord(const Args& args);

// Writes text to the file named by the flag ("o" for -o, "history", ...) atomically, or to
// stdout when the flag is absent or "-" (app/cli/Output.cpp). Throws UsageError for an empty
// name or a missing folder, kinstab::WriteError when the write fails.
void writeOutput(const Args& args, const std::string& flag, const std::string& text);
// The same checks on a name before the work starts.
void checkOutputPath(const std::string& flag, const std::string& path);

// Runs one command as kinstab-cli NAME ...: flushes stdout, and turns an exception into its
// message ("kinstab-cli NAME: ...") and exit code (app/cli/ExitCode.h).
int runCommand(int (*command)(const ArgList&), const char* name, const ArgList& args);

} // namespace kinstab::cli
