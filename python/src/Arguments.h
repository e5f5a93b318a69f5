// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Argument checks of the Python module. A bad argument raises ValueError with the message
// kinstab-cli gives for the same value, the flag replaced by the keyword: the CLI's
// "--mu 11: friction coefficient must be between 0 and 10" is "mu=11.0: friction coefficient
// must be between 0 and 10" here (tests/python/test_errors.py holds the two side by side).

#include "core/base/NumberInput.h"

#include <pybind11/pybind11.h>

#include <optional>
#include <string>

namespace kinstab::python {

std::string shown(double value); // as Python's repr shows the float

// ValueError "keyword=value: why".
[[noreturn]] void badArgument(const std::string& keyword, double value, const std::string& why);
[[noreturn]] void badArgument(const std::string& message);

// The value when finite, else ValueError "keyword=nan is not a finite number" (the CLI's
// "--mu 'nan' is not a finite number").
double finite(const std::string& keyword, double value);
// A declared input (core/base/NumberInput.h) given as a keyword: the value when it lies in its
// range, else a ValueError "mu=0.001: friction coefficient must be ..." (the same words as the
// command line's and the project reader's).
double keyword(const NumberInput& in, double value);
// A ValueError for a problem core found in what the keywords gave (the key is the keyword).
void refuse(const InputProblem& problem);

// One of the allowed words (named in the message "keyword='x' must be one of a|b|c").
std::string choice(const std::string& keyword, const std::string& value,
                   const std::string& allowedBarSeparated);

} // namespace kinstab::python
