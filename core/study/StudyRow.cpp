// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/StudyRow.h"

#include "core/base/TextInput.h"

namespace kinstab {

std::string studyDriverText(const StudyRow& r) {
    std::string s = "ground";
    if (r.level)
        s = "level " + std::to_string(*r.level);
    else if (r.floorPeriod)
        s = "floor T = " + formatDouble(*r.floorPeriod) +
            " s, ζ = " + formatDouble(r.floorDamping.value_or(0.0));
    if (r.motion && *r.motion == "fitted_sine") s += ", fitted sine";
    return s;
}

std::string studyRecordText(const StudyRow& r) {
    return r.polarity == std::optional<std::string>("inverted") ? r.record + " (inverted)"
                                                                : r.record;
}

} // namespace kinstab
