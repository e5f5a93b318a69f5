// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/MotionJson.h"

#include "core/base/TextInput.h"
#include "core/io/JsonValue.h"

#include <filesystem>

namespace kinstab {

using nlohmann::json;
namespace fs = std::filesystem;

std::string pathForProject(const std::string& file, const std::string& baseDir) {
    if (baseDir.empty() || file.empty()) return file;
    const fs::path p(file);
    if (!p.is_absolute()) return file;
    const fs::path rel = p.lexically_relative(fs::path(baseDir).lexically_normal());
    return rel.empty() ? file : rel.generic_string();
}

std::string pathFromProject(const std::string& stored, const std::string& baseDir) {
    const fs::path p(stored);
    if (baseDir.empty() || stored.empty() || p.is_absolute()) return stored;
    return (fs::path(baseDir) / p).lexically_normal().string();
}

bool leavesProjectFolder(const std::string& file, const std::string& baseDir) {
    if (baseDir.empty() || file.empty()) return false;
    const fs::path base = fs::absolute(fs::path(baseDir)).lexically_normal();
    const fs::path full = fs::absolute(base / fs::path(file)).lexically_normal();
    const fs::path rel = full.lexically_relative(base);
    return rel.empty() || *rel.begin() == "..";
}

namespace {

json recordToJson(const RecordExcitation& e, const std::string& baseDir) {
    json floor; // null: no floor filter
    if (e.floor) floor = {{"period_s", e.floor->period}, {"damping", e.floor->damping}};
    return {{"file", pathForProject(e.file, baseDir)},
            {"format", recordFormatName(e.read.format)},
            {"dt", orNull(e.read.dt)},
            {"unit", e.read.unit ? json(accelUnitName(*e.read.unit)) : json()},
            {"channel", e.read.channel},
            {"target_peak_g", orNull(e.targetPeak)},
            {"scale_factor", e.scaleFactor},
            {"floor_filter", floor}};
}

RecordReadOptions readOptionsFrom(const JsonReader& r) {
    RecordReadOptions o;
    const std::string format = r.text("format", "auto");
    const auto f = recordFormatFromName(format);
    if (!f)
        r.fail("format",
               quotedToken(format) + " must be auto, at2, cosmos, csmip, values or time-accel");
    o.format = *f;
    o.dt = r.optionalNumber("dt");
    if (const auto unit = r.optionalText("unit")) {
        o.unit = accelUnitFromName(*unit);
        if (!o.unit) r.fail("unit", quotedToken(*unit) + " must be g, m/s2, cm/s2, ft/s2 or in/s2");
    }
    o.channel = r.text("channel", "");
    return o;
}

RecordExcitation recordFrom(const JsonReader& r, const std::string& baseDir) {
    RecordExcitation e;
    const std::string file = r.pathText("file", "");
    if (file.empty()) r.fail("file", "missing (the accelerogram file)");
    e.file = pathFromProject(file, baseDir);
    e.read = readOptionsFrom(r);
    e.targetPeak = r.optionalNumber("target_peak_g");
    e.scaleFactor = r.number("scale_factor", 1.0);
    if (const auto f = r.optionalObject("floor_filter")) {
        FloorFilterParams p;
        p.period = f->requiredNumber("period_s");
        p.damping = f->number("damping", p.damping);
        e.floor = p;
    }
    if (const std::string err = validateRecordExcitation(e); !err.empty())
        throw JsonFieldError(err);
    return e;
}

} // namespace

json excitationToJson(const std::optional<RecordExcitation>& record, const std::string& baseDir) {
    if (!record) return {{"source", "sine"}};
    return {{"source", "record"}, {"record", recordToJson(*record, baseDir)}};
}

std::optional<RecordExcitation> excitationFromJson(const JsonReader& r,
                                                   const std::string& baseDir) {
    const auto x = r.optionalObject("excitation");
    if (!x) return std::nullopt;
    const std::string source = x->text("source", "sine");
    if (source == "sine") return std::nullopt;
    if (source != "record") x->fail("source", quotedToken(source) + " must be sine or record");
    return recordFrom(x->object("record"), baseDir);
}

void checkRecordFile(const RecordExcitation& e) {
    try {
        (void)readGroundRecord(e);
    } catch (const RecordError& err) {
        throw JsonFieldError("excitation.record.file = '" + elided(e.file, 1000) +
                             "': " + err.what());
    }
}

} // namespace kinstab
