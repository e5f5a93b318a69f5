// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The critical scale of a record: the smallest peak acceleration (g) of the scaled driving
// motion at which the 1-DOF slab collapses. gamma_c need not be monotone in the scale, so this
// is the scan-then-bisect search of CriticalAmplitude with the record's peak as the amplitude.

#include "core/records/Accelerogram.h"
#include "core/slab/Slab1DCase.h"
#include "core/sweep/CriticalAmplitude.h"

#include <memory>
#include <optional>

namespace kinstab {

struct RecordCriticalScale {
    std::optional<double> peak;   // g; nullopt when nothing up to the search limit collapses
    std::optional<double> factor; // peak / the unscaled motion's peak
    double motionPeak = 0;        // g, |peak| of the unscaled driving motion
    long runs = 0;
};

// The record run as a point function: amplitude = the peak (g) of the scaled motion; the
// frequency is ignored (a record has none). The motion's samples are built here, once, and shared
// by every run (throws std::invalid_argument when the motion cannot drive the slab).
PointFunction recordPoint(const Slab1DCase& c, const Accelerogram& motion);

RecordCriticalScale criticalRecordScale(const Slab1DCase& c, const Accelerogram& motion,
                                        const CriticalSearch& search = {});
// The same with the runs supplied by the caller (the GUI's returns at once after a cancel).
RecordCriticalScale criticalRecordScale(const PointFunction& point, double mu, double motionPeak,
                                        const CriticalSearch& search);

} // namespace kinstab
