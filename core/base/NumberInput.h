// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One numeric input as every front end reads it: its key, unit, the range it must lie in, its
// default and what it is. The project and study readers, the command line's flags, Python's
// keywords and the GUI's fields all read one declaration, so the same value gets the same
// answer in the same words everywhere; only the name in front differs ("slab.mu = 0.001",
// "--mu 0.001", "mu=0.001").

#include "core/base/Range.h"

#include <string>
#include <string_view>

namespace kinstab {

struct NumberInput {
    std::string_view key;  // snake_case: the project file's key and Python's keyword
    std::string_view unit; // "s", "g", "Hz", "in", "1/s"; empty for a ratio
    Range range;
    double fallback;            // the default when the input is not given
    std::string_view what;      // what the number is, as the message says it
    std::string_view flag = {}; // the command line's flag when it is not the key's spelling
};

// The command line's flag of an input: "--" and the key with '-' for '_' ("--wall-width-in"),
// or its own flag.
std::string flagName(const NumberInput& in);
std::string flagName(std::string_view key);

// "between 0.01 and 10" or "> 0 and at most 100", with the unit when there is one.
std::string rangeText(const NumberInput& in);

// An input that is wrong: which one (its key), its value and why, in words that follow
// "NAME VALUE: ". Empty key: nothing is wrong.
struct InputProblem {
    std::string key;
    double value = 0.0;
    std::string unit; // of the value, as the input declares it
    std::string why;
    bool empty() const { return key.empty(); }
};

// Nothing when x lies in the input's range; else "friction coefficient must be between 0.01
// and 10" for its key (NaN and infinities never lie in a range).
InputProblem checkInput(const NumberInput& in, double x);

// The problem as core and the project readers say it: "prefix.key = value unit: why", or
// empty when there is none.
std::string describe(const InputProblem& p, std::string_view prefix = {});
// The same under another name ("planar.fy_hz = 2000 Hz: ..."), for a reader whose key differs.
std::string describeAs(const InputProblem& p, std::string_view name);
// "2000 Hz: frequency along the walls must be ...": the problem after a name the caller writes.
std::string valueAndWhy(const InputProblem& p);

} // namespace kinstab
