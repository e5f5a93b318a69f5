// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/sweep/Grid.h"

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"
#include "core/excitation/EnvelopedSine.h"

#include <cmath>
#include <optional>
#include <sstream>

namespace kinstab {

namespace {
// Locale-independent: the GUI's process runs in the user's locale (decimal comma in German).
bool parseNumber(const std::string& s, double& out) {
    const std::optional<double> x = parseDouble(s);
    if (!x || !std::isfinite(*x)) return false;
    out = *x;
    return true;
}
} // namespace

std::vector<double> linspaceStep(double start, double stop, double step) {
    std::vector<double> v;
    const double n = (stop - start) / step;
    const long count = static_cast<long>(std::floor(n + 1e-9)) + 1;
    v.reserve(static_cast<std::size_t>(std::max(count, 0L)));
    for (long i = 0; i < count; ++i)
        v.push_back(start + static_cast<double>(i) * step);
    return v;
}

namespace {

// "start:stop:step", t trimmed and holding a ':'.
ParsedList parseRange(const std::string& t) {
    ParsedList out;
    std::vector<std::string> parts;
    std::stringstream ss(t);
    std::string item;
    while (std::getline(ss, item, ':'))
        parts.push_back(trimmed(item));
    double a = 0, b = 0, h = 0;
    if (parts.size() != 3 || !parseNumber(parts[0], a) || !parseNumber(parts[1], b) ||
        !parseNumber(parts[2], h)) {
        out.error = quotedToken(t) + " is not start:stop:step";
        return out;
    }
    if (h <= 0.0 || b < a) {
        out.error = quotedToken(t) + ": need step > 0 and stop >= start";
        return out;
    }
    if ((b - a) / h >= static_cast<double>(limits::kMaxGridPoints)) {
        out.error = quotedToken(t) + ": more than the limit of " +
                    std::to_string(limits::kMaxGridPoints) + " values";
        return out;
    }
    out.values = linspaceStep(a, b, h);
    return out;
}

// "x1,x2,...", t trimmed; no values when one is not a number or there are too many.
ParsedList parseCommaList(const std::string& t) {
    ParsedList out;
    std::stringstream ss(t);
    std::string item;
    while (std::getline(ss, item, ',')) {
        double x = 0;
        if (out.values.size() == limits::kMaxGridPoints) {
            out.error =
                "more than the limit of " + std::to_string(limits::kMaxGridPoints) + " values";
            out.values.clear();
            return out;
        }
        if (!parseNumber(trimmed(item), x)) {
            out.error = quotedToken(trimmed(item)) + " is not a number";
            out.values.clear();
            return out;
        }
        out.values.push_back(x);
    }
    return out;
}

} // namespace

ParsedList parseList(const std::string& text) {
    const std::string t = trimmed(text);
    if (t.empty()) {
        ParsedList out;
        out.error = "empty list";
        return out;
    }
    return t.find(':') != std::string::npos ? parseRange(t) : parseCommaList(t);
}

std::string validateGrid(const SweepGrid& g) {
    if (g.amplitudes.empty()) return "amplitudes: the grid is empty";
    if (g.frequencies.empty()) return "frequencies: the grid is empty";
    // Each point is an enveloped sine's amplitude and frequency (core/excitation/EnvelopedSine.h).
    for (double a : g.amplitudes)
        if (const InputProblem p = checkInput(kAmplitudeInput, a); !p.empty())
            return "amplitudes: " + valueAndWhy(p);
    for (double f : g.frequencies)
        if (const InputProblem p = checkInput(kFrequencyInput, f); !p.empty())
            return "frequencies: " + valueAndWhy(p);
    // Each axis may be long; the product is what a sweep computes and stores.
    if (g.amplitudes.size() > limits::kMaxGridPoints / g.frequencies.size())
        return "amplitudes: " + std::to_string(g.amplitudes.size()) + " amplitudes x " +
               std::to_string(g.frequencies.size()) + " frequencies, more than the limit of " +
               std::to_string(limits::kMaxGridPoints) + " points in a grid";
    return {};
}

} // namespace kinstab
