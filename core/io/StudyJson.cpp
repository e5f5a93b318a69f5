// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/StudyJson.h"
#include "core/io/StudySpecJson.h"

#include "core/base/TextInput.h"
#include "core/io/MotionJson.h"
#include "core/study/StudySpec.h"

namespace kinstab {

using nlohmann::json;

namespace {
// A path longer than any file system allows is a typing accident, not a file.
constexpr std::size_t kMaxStudyPathChars = 4096;

std::string pathFrom(const JsonReader& r, const std::string& key, const std::string& baseDir) {
    const std::string text = r.pathText(key, "");
    if (text.size() > kMaxStudyPathChars)
        r.fail(key, std::to_string(text.size()) + " characters, more than the limit of " +
                        std::to_string(kMaxStudyPathChars));
    return pathFromProject(text, baseDir);
}
} // namespace

json studyToJson(const ProjectStudy& s, const std::string& baseDir) {
    json j = {{"spec", pathForProject(s.spec, baseDir)}};
    if (!s.results.empty()) j["results"] = pathForProject(s.results, baseDir);
    return j;
}

std::optional<ProjectStudy> studyFromJson(const JsonReader& r, const std::string& baseDir) {
    if (!r.has("study") || r.raw("study").is_null()) return std::nullopt;
    const JsonReader s = r.object("study");
    ProjectStudy out;
    out.spec = pathFrom(s, "spec", baseDir);
    if (out.spec.empty()) s.fail("spec", "missing: the path of the study file");
    out.results = pathFrom(s, "results", baseDir);
    return out;
}

void checkStudyFile(const ProjectStudy& s) {
    try {
        (void)loadStudy(s.spec);
    } catch (const StudyError& e) {
        throw JsonFieldError("study.spec = " + quotedToken(s.spec) + ": " + e.what());
    }
}

} // namespace kinstab
