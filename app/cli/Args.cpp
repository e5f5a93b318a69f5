// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/Args.h"

#include "app/cli/Suggest.h"
#include "core/base/TextInput.h"
#include "core/sweep/Grid.h"

#include <algorithm>
#include <cmath>
#include <iostream>

namespace kinstab::cli {

namespace {

// "unknown flag '--amplitdue' (did you mean --amplitude?)", or the commands that have it.
std::string unknownFlag(const std::string& typed, const std::string& name,
                        const std::set<std::string>& flags, const std::set<std::string>& switches) {
    std::vector<std::string> own(flags.begin(), flags.end());
    own.insert(own.end(), switches.begin(), switches.end());
    std::string m = "unknown flag " + quotedToken(typed);
    if (const std::string near = nearest(name, own); !near.empty())
        return m + " (did you mean " + (near == "o" ? "-o" : "--" + near) + "?)";
    const std::vector<std::string> owners = commandsWithFlag(name);
    if (owners.empty()) return m;
    std::string list;
    for (const std::string& c : owners)
        list += (list.empty() ? "" : ", ") + c;
    return m + " (a flag of " + list + "; see kinstab-cli COMMAND --help)";
}

} // namespace

void warnIfNotInG(const Args& args) {
    // m/s² typed as g: 9.81 for 1 g. No recorded earthquake motion exceeds about 4 g in a
    // horizontal direction, so an amplitude above that is most likely in other units.
    auto warn = [](const std::string& flag, double g) {
        std::cerr << "kinstab-cli: warning: --" << flag << " " << formatDouble(g) << " g is above "
                  << formatDouble(kPlausibleAmplitudeG)
                  << " g, more than recorded earthquake motions reach: was it in m/s²? (1 g = "
                     "9.80665 m/s²)\n";
    };
    if (args.has("amplitude")) {
        const std::optional<double> a = parseDouble(args.text("amplitude"));
        if (a && *a > kPlausibleAmplitudeG) warn("amplitude", *a);
    }
    if (args.has("amplitudes")) {
        // A grid entirely above the bound; one that merely reaches past it is a study's choice.
        const ParsedList l = parseList(args.text("amplitudes"));
        if (l.error.empty() && !l.values.empty() &&
            *std::min_element(l.values.begin(), l.values.end()) > kPlausibleAmplitudeG)
            warn("amplitudes", *std::min_element(l.values.begin(), l.values.end()));
    }
}

Args::Args(const std::vector<std::string>& argv, const std::set<std::string>& flags,
           const std::set<std::string>& switches) {
    for (std::size_t i = 0; i < argv.size(); ++i) {
        const std::string& a = argv[i];
        std::string name;
        if (a == "-o")
            name = "o";
        else if (a.rfind("--", 0) == 0)
            name = a.substr(2);
        else
            throw UsageError("unexpected argument " + quotedToken(a));
        std::string value;
        const auto eq = name.find('=');
        const bool inlineValue = eq != std::string::npos;
        if (inlineValue) {
            value = name.substr(eq + 1);
            name = name.substr(0, eq);
        }
        if (switches.count(name)) {
            values_[name] = "1";
            continue;
        }
        if (!flags.count(name)) throw UsageError(unknownFlag(a, name, flags, switches));
        if (!inlineValue) {
            if (i + 1 >= argv.size()) throw UsageError("flag --" + name + " needs a value");
            value = argv[++i];
        }
        if (values_.count(name)) throw UsageError("flag --" + name + " given twice");
        if (name == "o" && value.empty())
            throw UsageError("-o \"\": the file name is empty (use - for stdout)");
        values_[name] = value;
    }
    warnIfNotInG(*this);
}

bool Args::has(const std::string& flag) const {
    return values_.count(flag) != 0;
}

std::string Args::text(const std::string& flag, const std::string& fallback) const {
    const auto it = values_.find(flag);
    return it == values_.end() ? fallback : it->second;
}

std::optional<std::string> Args::optionalText(const std::string& flag) const {
    const auto it = values_.find(flag);
    if (it == values_.end()) return std::nullopt;
    return it->second;
}

std::optional<double> Args::optionalNumber(const std::string& flag) const {
    const auto it = values_.find(flag);
    if (it == values_.end()) return std::nullopt;
    // std::from_chars: the C locale's syntax whatever the process locale.
    const std::optional<double> v = parseDouble(it->second);
    if (!v || !std::isfinite(*v))
        throw UsageError("--" + flag + " " + quotedToken(it->second) + " is not a finite number");
    return *v;
}

double Args::number(const std::string& flag, double fallback) const {
    return optionalNumber(flag).value_or(fallback);
}

std::optional<double> Args::optionalInput(const NumberInput& in) const {
    const std::string flag = flagName(in).substr(2);
    const std::optional<double> x = optionalNumber(flag);
    if (x) refuse(checkInput(in, *x), flag);
    return x;
}

double Args::input(const NumberInput& in) const {
    return optionalInput(in).value_or(in.fallback);
}

void Args::refuse(const InputProblem& problem, const std::string& flag) const {
    if (problem.empty()) return;
    const std::string f = flag.empty() ? flagName(problem.key).substr(2) : flag;
    const std::string shown = has(f) ? text(f) : formatDouble(problem.value);
    throw UsageError("--" + f + " " + shown + ": " + problem.why);
}

double Args::requiredNumber(const std::string& flag) const {
    const auto v = optionalNumber(flag);
    if (!v) throw UsageError("missing required flag --" + flag);
    return *v;
}

int Args::integer(const std::string& flag, int fallback) const {
    const auto v = optionalNumber(flag);
    if (!v) return fallback;
    if (*v != std::floor(*v) || std::abs(*v) > 1e9)
        throw UsageError("--" + flag + " " + quotedToken(text(flag)) + " is not a whole number");
    return static_cast<int>(*v);
}

std::vector<double> Args::list(const std::string& flag) const {
    const auto t = optionalText(flag);
    if (!t) throw UsageError("missing required flag --" + flag);
    const ParsedList p = parseList(*t);
    if (!p.error.empty()) throw UsageError("--" + flag + ": " + p.error);
    return p.values;
}

std::string Args::choice(const std::string& flag, const std::set<std::string>& allowed,
                         const std::string& fallback) const {
    const auto t = optionalText(flag);
    if (!t) return fallback;
    if (!allowed.count(*t)) {
        std::string names;
        for (const auto& a : allowed)
            names += (names.empty() ? "" : "|") + a;
        throw UsageError("--" + flag + " " + quotedToken(*t) + " must be one of " + names);
    }
    return *t;
}

} // namespace kinstab::cli
