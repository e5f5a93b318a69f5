// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Who signs the report and for whom: the engineer, registration, firm, client, project number,
// site address, prepared/checked by and the revision history. Stored in the project file under
// "info"; printed on the report's title block, signature/seal block and revision table. Every
// field is optional one-line text of at most limits::kMaxNameChars characters (a revision mark
// limits::kMaxRevisionIdChars), without control or bidirectional formatting characters
// (core/base/DisplayText.h); a revision date is ISO 8601 (YYYY-MM-DD) so that it reads the same
// in every locale.

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace kinstab {

struct Revision {
    std::string id;          // "0", "A", "P1" ...
    std::string date;        // "2026-11-24"
    std::string description; // "Issued for permit"
};

struct ProjectInfo {
    std::string engineer;     // engineer of record
    std::string registration; // licence or registration number
    std::string firm;
    std::string client;
    std::string projectNumber;
    std::string siteAddress;
    std::string preparedBy;
    std::string checkedBy;
    std::vector<Revision> revisions; // oldest first; the last is the current issue

    bool empty() const;
};

// Empty when fine; else "info.checked_by: 240 characters, more than the limit of 200",
// "info.registration: contains U+202E (a bidirectional override) at character 8" or
// "info.revisions[1].date = '24.11.2026': must be a date YYYY-MM-DD".
std::string validateProjectInfo(const ProjectInfo& info);

nlohmann::json projectInfoToJson(const ProjectInfo& info);
// j: the "info" object. Throws JsonFieldError naming the field ("info.engineer: expected text").
ProjectInfo projectInfoFromJson(const nlohmann::json& j);

} // namespace kinstab
