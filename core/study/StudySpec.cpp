// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/StudySpec.h"

#include "core/base/TextInput.h"

namespace kinstab {

std::string intensityName(const IntensityMeasure& im) {
    if (im.kind == IntensityMeasure::Kind::Pga) return "pga";
    return "sa(" + formatDouble(im.period) + "s/" + formatDouble(100.0 * im.damping) + "%)";
}

std::string motionName(StudyMotion m) {
    return m == StudyMotion::Record ? "record" : "fitted_sine";
}

std::optional<StudyMotion> motionFromName(const std::string& name) {
    for (StudyMotion m : {StudyMotion::Record, StudyMotion::FittedSine})
        if (name == motionName(m)) return m;
    return std::nullopt;
}

} // namespace kinstab
