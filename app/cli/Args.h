// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Command-line flags of one subcommand: --name value pairs, checked against the flags the
// subcommand declares. Every problem is a UsageError naming the flag and the value (exit 2).

#include "core/base/NumberInput.h"

#include <map>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace kinstab::cli {

struct UsageError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Above this, an amplitude given in g (--amplitude, or every value of --amplitudes) draws a
// warning on stderr: it looks like m/s² (9.81 typed for 1 g). The run goes on.
inline constexpr double kPlausibleAmplitudeG = 4.0;

class Args;
void warnIfNotInG(const Args& args);

class Args {
public:
    // flags: the names this subcommand accepts (without "--"); switches take no value.
    Args(const std::vector<std::string>& argv, const std::set<std::string>& flags,
         const std::set<std::string>& switches = {});

    bool has(const std::string& flag) const;
    std::string text(const std::string& flag, const std::string& fallback = {}) const;
    std::optional<std::string> optionalText(const std::string& flag) const;
    double number(const std::string& flag, double fallback) const;
    std::optional<double> optionalNumber(const std::string& flag) const;
    double requiredNumber(const std::string& flag) const;
    int integer(const std::string& flag, int fallback) const;
    std::vector<double> list(const std::string& flag) const; // required LIST
    // A declared input (core/base/NumberInput.h) under its flag: its default when absent, else
    // a number in its range (UsageError "--mu 0.001: friction coefficient must be ...").
    double input(const NumberInput& in) const;
    std::optional<double> optionalInput(const NumberInput& in) const;
    // Throws a UsageError for a problem core found in what the flags gave, naming the flag
    // (flagName of the problem's key unless flag is given) and the value as typed.
    void refuse(const InputProblem& problem, const std::string& flag = {}) const;
    // One of the allowed words, or the fallback when absent.
    std::string choice(const std::string& flag, const std::set<std::string>& allowed,
                       const std::string& fallback) const;

private:
    std::map<std::string, std::string> values_;
};

} // namespace kinstab::cli
