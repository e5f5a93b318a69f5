// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// kinstab-cli's exit codes, so that a script can tell what to do next (kinstab-cli --help,
// man kinstab-cli, README):
//   0 success;
//   2 bad input: the message names the flag, field or file and the value (fix the input);
//   3 an output could not be written: full disk, full or closed stdout, no permission (retry
//     once there is room; any file that was there before is left as it was);
//   4 the model gave no finite result for accepted input: a NaN or infinity, or a bounded
//     search that reached its bound (kinstab::InternalError; report it with the input);
//   1 anything else: a bug in kinstab.

#include <exception>
#include <string>

namespace kinstab::cli {

struct Failure {
    int code;
    std::string prefix; // before the exception's message: "error: ", "no finite result: ", ...
};

// The exit code and message prefix for an exception a command ended with.
Failure failureOf(const std::exception& e);

} // namespace kinstab::cli
