// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/PlanarJson.h"

#include "core/base/TextInput.h"
#include "core/io/MotionJson.h"

namespace kinstab {

using nlohmann::json;

json planarSettingsToJson(const PlanarSettings& s, const std::string& baseDir) {
    const json vertical = s.vertical == VerticalSource::File
                              ? json{{"file", pathForProject(s.verticalPath, baseDir)}}
                              : json(verticalSourceName(s.vertical));
    return {{"fy_hz", s.fyHz},
            {"ay_ratio", s.ayRatio},
            {"theta", s.theta},
            {"normalization", normalizationName(s.normalization)},
            {"vertical", vertical}};
}

namespace {
void verticalFrom(const JsonReader& r, PlanarSettings& s, const std::string& baseDir) {
    if (!r.has("vertical")) return;
    const json& v = r.raw("vertical");
    if (v.is_object()) {
        const JsonReader o(v, r.field("vertical"));
        s.vertical = VerticalSource::File;
        s.verticalPath = o.pathText("file", "");
        if (s.verticalPath.empty()) o.fail("file", "'': name the vertical record file");
        s.verticalPath = pathFromProject(s.verticalPath, baseDir);
        return;
    }
    if (!v.is_string()) r.fail("vertical", "expected \"none\", \"rsn68_up\" or {\"file\": PATH}");
    const std::string name = v.get<std::string>();
    const auto source = verticalSourceFromName(name);
    if (!source || *source == VerticalSource::File)
        r.fail("vertical", quotedToken(name) + " must be none, rsn68_up or {\"file\": PATH}");
    s.vertical = *source;
}
} // namespace

PlanarSettings planarSettingsFromJson(const JsonReader& r, const std::string& baseDir) {
    PlanarSettings s;
    s.fyHz = r.number("fy_hz", s.fyHz);
    s.ayRatio = r.number("ay_ratio", s.ayRatio);
    s.theta = r.number("theta", s.theta);
    const std::string norm = r.text("normalization", normalizationName(s.normalization));
    const auto n = normalizationFromName(norm);
    if (!n) r.fail("normalization", quotedToken(norm) + " must be product or envelope");
    s.normalization = *n;
    verticalFrom(r, s, baseDir);
    if (const std::string e = validatePlanarSettings(s); !e.empty()) throw JsonFieldError(e);
    return s;
}

} // namespace kinstab
