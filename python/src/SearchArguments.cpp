// SPDX-License-Identifier: GPL-3.0-or-later
#include "python/src/SearchArguments.h"

#include "python/src/Arguments.h"

namespace kinstab::python {

CriticalSearch searchFrom(double maxAmplitude, double scanStep, double tolerance) {
    CriticalSearch s;
    s.to = keyword(kMaxAmplitudeInput, maxAmplitude);
    s.scanStep = keyword(kScanStepInput, scanStep);
    s.tolerance = keyword(kToleranceInput, tolerance);
    refuse(checkCriticalSearch(s));
    return s;
}

} // namespace kinstab::python
