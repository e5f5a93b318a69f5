// SPDX-License-Identifier: GPL-3.0-or-later
#include "python/src/Arguments.h"

#include <cmath>

namespace py = pybind11;

namespace kinstab::python {

std::string shown(double value) {
    return py::repr(py::float_(value)).cast<std::string>();
}

void badArgument(const std::string& keyword, double value, const std::string& why) {
    throw py::value_error(keyword + "=" + shown(value) + ": " + why);
}

void badArgument(const std::string& message) {
    throw py::value_error(message);
}

double finite(const std::string& keyword, double value) {
    if (!std::isfinite(value))
        throw py::value_error(keyword + "=" + shown(value) + " is not a finite number");
    return value;
}

void refuse(const InputProblem& problem) {
    if (!problem.empty()) badArgument(problem.key, problem.value, problem.why);
}

double keyword(const NumberInput& in, double value) {
    finite(std::string(in.key), value);
    refuse(checkInput(in, value));
    return value;
}

std::string choice(const std::string& keyword, const std::string& value,
                   const std::string& allowedBarSeparated) {
    const std::string bars = "|" + allowedBarSeparated + "|";
    if (value.empty() || value.find('|') != std::string::npos ||
        bars.find("|" + value + "|") == std::string::npos)
        throw py::value_error(keyword + "='" + value + "' must be one of " + allowedBarSeparated);
    return value;
}

} // namespace kinstab::python
