// SPDX-License-Identifier: GPL-3.0-or-later
// One command run the way kinstab-cli and kinstab-report both run theirs.

#include "app/cli/Commands.h"
#include "app/cli/ExitCode.h"
#include "core/io/AtomicFile.h"

#include <exception>
#include <iostream>

namespace kinstab::cli {

int runCommand(int (*command)(const ArgList&), const char* name, const ArgList& args) {
    try {
        const int code = command(args);
        kinstab::flushStandardOutput(); // a full stdout is a failed run, not a silent loss
        return code;
    } catch (const std::exception& e) {
        const Failure f = failureOf(e);
        std::cerr << "kinstab-cli " << name << ": " << f.prefix << e.what() << "\n";
        return f.code;
    }
}

} // namespace kinstab::cli
