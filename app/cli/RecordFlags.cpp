// SPDX-License-Identifier: GPL-3.0-or-later
#include "app/cli/RecordFlags.h"

#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"

namespace kinstab::cli {

std::set<std::string> recordReadFlagNames() {
    return {"record-format", "record-dt", "record-unit", "record-channel"};
}

RecordReadOptions recordReadOptionsFromFlags(const Args& args) {
    RecordReadOptions o;
    o.format = *recordFormatFromName(args.choice(
        "record-format", {"auto", "at2", "cosmos", "csmip", "values", "time-accel"}, "auto"));
    o.dt = args.optionalInput(kRecordDtInput);
    if (args.has("record-unit")) {
        o.unit = accelUnitFromName(args.text("record-unit"));
        if (!o.unit)
            throw UsageError("--record-unit " + args.text("record-unit") +
                             ": must be one of g, m/s2, cm/s2, ft/s2, in/s2");
    }
    o.channel = args.text("record-channel");
    if (o.format == RecordFormat::Values && !o.dt)
        throw UsageError("--record-format values: needs --record-dt (the file has no time column)");
    return o;
}

Accelerogram readRecordFromFlag(const Args& args, const std::string& fileFlag) {
    const std::string path = args.text(fileFlag);
    if (path.empty()) throw UsageError("--" + fileFlag + ": needs a file name");
    try {
        return readRecord(path, recordReadOptionsFromFlags(args));
    } catch (const RecordError& e) {
        throw UsageError("--" + fileFlag + " " + path + ": " + e.what());
    }
}

std::optional<FloorFilterParams> floorFilterFromFlags(const Args& args) {
    if (!args.has("floor-period")) {
        if (args.has("damping"))
            throw UsageError("--damping " + args.text("damping") + ": needs --floor-period");
        return std::nullopt;
    }
    FloorFilterParams p;
    p.period = args.requiredNumber("floor-period");
    p.damping = args.number("damping", 0.02);
    const InputProblem e = checkFloorFilter(p);
    args.refuse(e, e.key == "period_s" ? "floor-period" : "damping");
    return p;
}

RecordExcitation recordExcitationFromFlags(const Args& args, const std::string& fileFlag) {
    RecordExcitation e;
    e.file = args.text(fileFlag);
    if (e.file.empty()) throw UsageError("--" + fileFlag + ": needs a file name");
    e.read = recordReadOptionsFromFlags(args);
    e.floor = floorFilterFromFlags(args);
    if (args.has("amplitude") && args.has("scale-factor"))
        throw UsageError("--scale-factor " + args.text("scale-factor") +
                         ": --amplitude and --scale-factor exclude each other");
    e.targetPeak = args.optionalInput(kTargetPeakInput);
    e.scaleFactor = args.input(kScaleFactorInput);
    return e;
}

} // namespace kinstab::cli
