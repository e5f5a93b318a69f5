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
#include <string_view>

namespace kinstab::python {

// A number argument that is not a bool. pybind11 converts True to 1.0 for a double, but a flag
// passed where a number belongs is a slip (simulate(True, 1) ran at 1 g): True, False and NumPy's
// bools raise TypeError. Any other int, float or object with __float__ converts as for a double.
struct Real {
    double value = 0;
    operator double() const { return value; }
};
inline std::optional<double> real(std::optional<Real> r) {
    return r ? std::optional<double>(r->value) : std::nullopt;
}

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

namespace pybind11::detail {

template <> struct type_caster<kinstab::python::Real> {
    PYBIND11_TYPE_CASTER(kinstab::python::Real, const_name("float"));

    bool load(handle src, bool convert) {
        if (!src || PyBool_Check(src.ptr())) return false;
        const std::string_view type = Py_TYPE(src.ptr())->tp_name;
        if (type == "numpy.bool_" || type == "numpy.bool") return false;
        make_caster<double> number;
        if (!number.load(src, convert)) return false;
        value.value = cast_op<double>(number);
        return true;
    }
    static handle cast(kinstab::python::Real r, return_value_policy, handle) {
        return PyFloat_FromDouble(r.value);
    }
};

} // namespace pybind11::detail
