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
int runReport(const ArgList& args);
int runRecord(const ArgList& args);
int runFriction(const ArgList& args);
int runFloors(const ArgList& args);

class Args;
// simulate --record FILE (SimulateRecord.cpp), called by runSimulate.
int runSimulateRecord(const Args& args);

// Writes text to the file named by -o, or to stdout when there is none (atomically: a
// temporary file renamed into place).
void writeOutput(const std::string& path, const std::string& text);

} // namespace kinstab::cli
