// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/StudySpec.h"

#include "core/base/NameTable.h"

#include "core/base/TextInput.h"

namespace kinstab {

std::string intensityName(const IntensityMeasure& im) {
    if (im.kind == IntensityMeasure::Kind::Pga) return "pga";
    return "sa(" + formatDouble(im.period) + "s/" + formatDouble(100.0 * im.damping) + "%)";
}

// StudyMotion's names, in its declaration order (Record, FittedSine).
constexpr std::array<const char*, 2> kStudyMotionNames = {"record", "fitted_sine"};
static_assert(kStudyMotionNames.size() == static_cast<std::size_t>(StudyMotion::FittedSine) + 1);

std::string motionName(StudyMotion m) {
    return enumName(kStudyMotionNames, m);
}

std::optional<StudyMotion> motionFromName(const std::string& name) {
    return enumFromName<StudyMotion>(kStudyMotionNames, name);
}

} // namespace kinstab
