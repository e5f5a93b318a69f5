// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Every number a slab result promises is finite: tau_c when it collapsed, where the run ended,
// the residual and largest displacement, and each recorded event's time, displacement and
// velocity (core/slab/SlabRecorder.h). A solver that breaks this reports an internal failure
// instead of a wrong verdict, and the command line refuses to write it (exit 3).

#include "core/slab/SlabTypes.h"

#include <string>
#include <vector>

namespace kinstab {

// Starts the failure text of a result the program cannot stand behind (not a limit the
// user's input reached, such as the chattering guard).
inline constexpr const char* kInternalFailure = "internal error: ";

// The first promised number that is not finite, named with its value ("tau_c = nan");
// empty when there is none.
std::string nonFiniteField(const SlabResult& r);
// The same for recorded events ("event 3 (stick) tau = inf").
std::string nonFiniteField(const std::vector<SlabEvent>& events);
// Turns a result with a non-finite promised number (in itself, or in the events when given) into
// a Failed one whose failure starts with kInternalFailure and names the field; leaves a sound
// result alone.
void failIfNonFinite(SlabResult& r, const std::vector<SlabEvent>& events = {});
bool isInternalFailure(const SlabResult& r);
// Throws InternalError naming the case when r is an internal failure or has a non-finite
// promised number.
void requireSound(const SlabResult& r, const std::string& caseName);

} // namespace kinstab
