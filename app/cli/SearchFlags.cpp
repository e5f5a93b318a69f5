// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/SearchFlags.h"

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"

#include <charconv>
#include <string>

namespace kinstab::cli {

namespace {
// Three significant digits, locale-independent.
std::string shortNumber(double x) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::general, 3);
    return std::string(buf, r.ptr);
}
} // namespace

std::set<std::string> searchFlagNames() {
    return {"max-amplitude", "scan-step", "tolerance"};
}

CriticalSearch criticalSearchFromFlags(const Args& args) {
    CriticalSearch search;
    search.to = args.number("max-amplitude", 5.0);
    search.scanStep = args.number("scan-step", 0.01);
    search.tolerance = args.number("tolerance", 1e-6);
    if (search.to <= 0.0 || search.to > limits::kMaxAmplitudeG)
        throw UsageError("--max-amplitude " + args.text("max-amplitude") +
                         ": must be > 0 and at most " + formatDouble(limits::kMaxAmplitudeG));
    if (search.scanStep <= 0.0 || search.scanStep > search.to)
        throw UsageError("--scan-step " + args.text("scan-step") +
                         ": must be > 0 and below --max-amplitude");
    // The scan runs the model once per step from mu up: a bound on the steps bounds the run.
    const double finestStep = search.to / static_cast<double>(kMaxScanPoints);
    if (search.scanStep < finestStep)
        throw UsageError("--scan-step " + args.text("scan-step") + ": at most " +
                         std::to_string(kMaxScanPoints) + " scan points; the smallest step for " +
                         "--max-amplitude " + shortNumber(search.to) + " is " +
                         shortNumber(finestStep));
    if (search.tolerance <= 0.0 || search.tolerance > search.scanStep)
        throw UsageError("--tolerance " + args.text("tolerance") +
                         ": must be > 0 and at most --scan-step");
    // Double precision resolves amplitudes near A to about 4 ulps of A; a bisection asked to
    // go finer could only repeat its end points.
    const double finest = smallestTolerance(search.to);
    if (search.tolerance < finest)
        throw UsageError("--tolerance " + args.text("tolerance") +
                         ": below what double precision resolves at --max-amplitude " +
                         shortNumber(search.to) + "; the smallest is " + shortNumber(finest));
    return search;
}

} // namespace kinstab::cli
