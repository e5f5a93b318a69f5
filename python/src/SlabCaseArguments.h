// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The 1-DOF case from keyword arguments, checked as kinstab-cli checks its model flags
// (app/cli/ModelFlags.cpp): same limits, same messages, keyword for flag.

#include "core/slab/Slab1DCase.h"
#include "core/slab/SlabInputs.h"

#include <optional>
#include <string>

namespace kinstab::python {

struct SlabCaseArguments {
    Envelope envelope = Envelope::fromPreset(EnvelopePreset::Moderate);
    std::optional<double> tstar;
    std::optional<double> wallWidthIn;
    double mu = kMuInput.fallback;
    double limit = kLimitInput.fallback;
    std::optional<double> duration;
    std::string scale = "tau_max";
    std::string solver = "exact";
    double paperSteps = kPaperStepsInput.fallback;
};

// Throws ValueError naming the keyword and value.
Slab1DCase slabCaseFrom(const SlabCaseArguments& a);
// Envelope(alpha, beta) checked by the core's validateEnvelope ("alpha/beta: ...").
Envelope customEnvelope(double alpha, double beta);
Envelope presetEnvelope(const std::string& name);

} // namespace kinstab::python
