// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A recorded horizontal motion as a project's excitation (docs/theory.md §7; docs/user-guide.md):
// the accelerogram file and how to read it, the scaling (to a target peak in g, or by a factor) and
// the optional floor filter (T, zeta) that turns a ground record into the floor motion the slab
// feels. The scaling applies to the driving motion, i.e. after the floor filter: its peak is what
// the slab sees.

#include "core/base/InputLimits.h"
#include "core/base/NumberInput.h"
#include "core/excitation/FloorFilter.h"
#include "core/records/Accelerogram.h"
#include "core/records/RecordReader.h"

#include <optional>
#include <string>

namespace kinstab {

// A record's inputs, declared once. The sample interval of a headerless file (limits::
// kMinRecordDt to kMaxRecordDt: the readers refuse any other), the peak the driving motion is
// scaled to, or the factor it is multiplied by. The command line spells them --record-dt,
// --amplitude and --scale-factor.
inline constexpr NumberInput kRecordDtInput{
    "dt", "s", {limits::kMinRecordDt, limits::kMaxRecordDt}, 0.01, "sample interval", "record-dt"};
inline constexpr NumberInput kTargetPeakInput{
    "target_peak_g", "g", {0.0, limits::kMaxAmplitudeG, true}, 1.0, "target peak", "amplitude"};
inline constexpr NumberInput kScaleFactorInput{
    "scale_factor", "", {0.0, 1e6, true}, 1.0, "scale factor"};

struct RecordExcitation {
    std::string file;                       // path of the accelerogram (absolute once loaded)
    RecordReadOptions read;                 // format, dt and unit hints for headerless text
    std::optional<double> targetPeak;       // g: scale the driving motion to this peak
    double scaleFactor = 1.0;               // used when there is no target peak
    std::optional<FloorFilterParams> floor; // none: the record drives the slab directly
};

// Empty when fine, else "excitation.record.FIELD = VALUE: ..." (the project's field names).
std::string validateRecordExcitation(const RecordExcitation& e);

// The ground record as read from e.file; throws RecordError ("FILE:LINE: message").
Accelerogram readGroundRecord(const RecordExcitation& e);
// The motion under the slab: the ground record, through the floor filter when there is one.
Accelerogram drivingMotion(const RecordExcitation& e, const Accelerogram& ground);
// The peak (g) the scaled driving motion has: the target peak, or the factor times its peak.
double scaledPeak(const RecordExcitation& e, const Accelerogram& motion);

} // namespace kinstab
