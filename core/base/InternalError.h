// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A result the program cannot stand behind: a NaN or infinity where a number is promised, or a
// bounded search that reached its bound. Not the user's fault (that is a usage error), so the
// command line reports it as "internal error: ..." with exit code 3 instead of writing it.

#include <stdexcept>
#include <string>

namespace kinstab {

class InternalError : public std::runtime_error {
public:
    explicit InternalError(const std::string& what) : std::runtime_error(what) {}
};

} // namespace kinstab
