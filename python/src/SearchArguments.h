// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The critical-amplitude search from keyword arguments, checked as kinstab-cli checks
// --max-amplitude, --scan-step and --tolerance (app/cli/SearchFlags.cpp).

#include "core/sweep/CriticalAmplitude.h"

namespace kinstab::python {

CriticalSearch searchFrom(double maxAmplitude, double scanStep, double tolerance);

} // namespace kinstab::python
