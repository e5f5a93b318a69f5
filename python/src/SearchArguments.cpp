// SPDX-License-Identifier: GPL-3.0-or-later
#include "python/src/SearchArguments.h"

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"
#include "core/check/DesignCheck.h"
#include "python/src/Arguments.h"

namespace kinstab::python {

CriticalSearch searchFrom(double maxAmplitude, double scanStep, double tolerance) {
    CriticalSearch s;
    s.to = finite("max_amplitude", maxAmplitude);
    s.scanStep = finite("scan_step", scanStep);
    s.tolerance = finite("tolerance", tolerance);
    if (!(s.to > 0.0 && s.to <= limits::kMaxAmplitudeG))
        badArgument("max_amplitude", s.to,
                    "must be > 0 and at most " + formatDouble(limits::kMaxAmplitudeG));
    if (!(s.scanStep > 0.0 && s.scanStep <= s.to))
        badArgument("scan_step", s.scanStep, "must be > 0 and below --max-amplitude");
    if (!(s.tolerance > 0.0 && s.tolerance <= s.scanStep))
        badArgument("tolerance", s.tolerance, "must be > 0 and at most --scan-step");
    // The search's own bounds (scan points, the tolerance double precision resolves), declared
    // once in core and named by the keyword here: a ValueError, as the CLI's exit 2.
    if (const std::string e = validateCriticalSearch(s, ""); !e.empty()) badArgument(e);
    return s;
}

} // namespace kinstab::python
