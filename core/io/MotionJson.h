// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The project's excitation source as JSON (docs/user-guide.md): the enveloped sine of
// "slab.envelope" (today's default, and what a project without the key means) or a record:
//   "excitation": {"source": "sine"}
//   "excitation": {"source": "record", "record": {"file": "../records/X.AT2", "format": "auto",
//       "dt": null, "unit": null, "channel": "", "target_peak_g": 0.4, "scale_factor": 1,
//       "floor_filter": {"period_s": 1.0, "damping": 0.02} | null}}
// The file is stored relative to the project's directory when one is given, and resolved
// against it on load; a file that cannot be read names the field and the path.

#include "core/excitation/RecordExcitation.h"
#include "core/io/JsonReader.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace kinstab {

// baseDir: the project file's directory ("" keeps paths as they are).
nlohmann::json excitationToJson(const std::optional<RecordExcitation>& record,
                                const std::string& baseDir);
// Reads the "excitation" object (r is the project's top level); none means the sine.
// Throws JsonFieldError naming the field.
std::optional<RecordExcitation> excitationFromJson(const JsonReader& r, const std::string& baseDir);
// Reads the record once to check it: throws JsonFieldError "excitation.record.file = 'PATH':
// FILE:LINE: message" when the file is missing or broken.
void checkRecordFile(const RecordExcitation& e);

// Path helpers: relative to baseDir when both are given, else unchanged; and back.
std::string pathForProject(const std::string& file, const std::string& baseDir);
std::string pathFromProject(const std::string& stored, const std::string& baseDir);
// True when file (absolute, or relative to baseDir) lies outside the folder baseDir and its
// subfolders ("../other/X.AT2", "/data/X.AT2"): such a project is not self-contained when
// copied, so the GUI and the report name the file as being outside the project's folder.
bool leavesProjectFolder(const std::string& file, const std::string& baseDir);

} // namespace kinstab
