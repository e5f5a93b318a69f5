// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/excitation/RecordExcitation.h"

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"

#include <cmath>
#include <sstream>

namespace kinstab {

namespace {
std::string fieldError(const std::string& field, double value, const std::string& rule) {
    std::ostringstream s;
    s << "excitation.record." << field << " = " << value << ": " << rule;
    return s.str();
}
} // namespace

std::string validateRecordExcitation(const RecordExcitation& e) {
    if (e.file.empty()) return "excitation.record.file: missing (the accelerogram file)";
    if (e.read.dt)
        if (const InputProblem p = checkInput(kRecordDtInput, *e.read.dt); !p.empty())
            return describe(p, "excitation.record.");
    if (e.read.format == RecordFormat::Values && !e.read.dt)
        return "excitation.record.dt: missing (format 'values' has no time column)";
    if (e.targetPeak)
        if (const InputProblem p = checkInput(kTargetPeakInput, *e.targetPeak); !p.empty())
            return describe(p, "excitation.record.");
    if (const InputProblem p = checkInput(kScaleFactorInput, e.scaleFactor); !p.empty())
        return describe(p, "excitation.record.");
    if (e.floor) {
        if (const InputProblem f = checkFloorFilter(*e.floor); !f.empty())
            return fieldError("floor_filter." + f.key, f.value, f.why);
    }
    return {};
}

Accelerogram readGroundRecord(const RecordExcitation& e) {
    return readRecord(e.file, e.read);
}

Accelerogram drivingMotion(const RecordExcitation& e, const Accelerogram& ground) {
    return e.floor ? floorMotion(ground, *e.floor) : ground;
}

double scaledPeak(const RecordExcitation& e, const Accelerogram& motion) {
    return e.targetPeak ? *e.targetPeak : e.scaleFactor * std::abs(motion.peak().value);
}

} // namespace kinstab
