// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Argument checks of the Python module. A bad argument raises ValueError with the message
// kinstab-cli gives for the same value, the flag replaced by the keyword: the CLI's
// "--mu 11: friction coefficient must be between 0 and 10" is "mu=11.0: friction coefficient
// must be between 0 and 10" here (tests/python/test_errors.py holds the two side by side).

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

// One of the allowed words (named in the message "keyword='x' must be one of a|b|c").
std::string choice(const std::string& keyword, const std::string& value,
                   const std::string& allowedBarSeparated);

} // namespace kinstab::python
