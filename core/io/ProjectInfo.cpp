// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/ProjectInfo.h"

#include "core/base/DisplayText.h"
#include "core/base/InputLimits.h"
#include "core/base/TextInput.h"
#include "core/io/JsonReader.h"

#include <utility>

namespace kinstab {

namespace {

using nlohmann::json;
using TextField = std::pair<const char*, std::string ProjectInfo::*>;

// The JSON key of each text field, in title-block order.
constexpr TextField kFields[] = {
    {"engineer", &ProjectInfo::engineer},
    {"registration", &ProjectInfo::registration},
    {"firm", &ProjectInfo::firm},
    {"client", &ProjectInfo::client},
    {"project_number", &ProjectInfo::projectNumber},
    {"site_address", &ProjectInfo::siteAddress},
    {"prepared_by", &ProjectInfo::preparedBy},
    {"checked_by", &ProjectInfo::checkedBy},
};

// A one-line text of the title block (core/base/DisplayText.h): no controls, no bidirectional
// formatting, at most limits::kMaxNameChars characters.
std::string badText(const std::string& field, const std::string& text) {
    return checkDisplayText(field, text, limits::kMaxNameChars, TextLines::Single);
}

bool isDigit(char c) {
    return c >= '0' && c <= '9';
}

// YYYY-MM-DD with a month 01-12 and a day 01-31 (the calendar is the engineer's business).
bool isIsoDate(const std::string& d) {
    if (d.size() != 10 || d[4] != '-' || d[7] != '-') return false;
    for (int i : {0, 1, 2, 3, 5, 6, 8, 9})
        if (!isDigit(d[static_cast<std::size_t>(i)])) return false;
    const int month = (d[5] - '0') * 10 + (d[6] - '0');
    const int day = (d[8] - '0') * 10 + (d[9] - '0');
    return month >= 1 && month <= 12 && day >= 1 && day <= 31;
}

std::string validateRevision(const Revision& r, const std::string& field) {
    if (r.id.empty()) return field + ".id: empty (a revision needs a mark such as 0 or A)";
    std::string e =
        checkDisplayText(field + ".id", r.id, limits::kMaxRevisionIdChars, TextLines::Single);
    if (e.empty() && !isIsoDate(r.date))
        e = field + ".date = " + quotedToken(r.date) + ": must be a date YYYY-MM-DD";
    if (e.empty()) e = badText(field + ".description", r.description);
    return e;
}

} // namespace

bool ProjectInfo::empty() const {
    for (const auto& [key, member] : kFields)
        if (!(this->*member).empty()) return false;
    return revisions.empty();
}

std::string validateProjectInfo(const ProjectInfo& info) {
    for (const auto& [key, member] : kFields)
        if (std::string e = badText(std::string("info.") + key, info.*member); !e.empty()) return e;
    if (info.revisions.size() > limits::kMaxRevisions)
        return "info.revisions: " + std::to_string(info.revisions.size()) +
               " revisions, more than the limit of " + std::to_string(limits::kMaxRevisions);
    for (std::size_t i = 0; i < info.revisions.size(); ++i)
        if (std::string e =
                validateRevision(info.revisions[i], "info.revisions[" + std::to_string(i) + "]");
            !e.empty())
            return e;
    return {};
}

json projectInfoToJson(const ProjectInfo& info) {
    json j = json::object();
    for (const auto& [key, member] : kFields)
        j[key] = info.*member;
    json revisions = json::array();
    for (const Revision& r : info.revisions)
        revisions.push_back({{"id", r.id}, {"date", r.date}, {"description", r.description}});
    j["revisions"] = revisions;
    return j;
}

ProjectInfo projectInfoFromJson(const json& j) {
    const JsonReader r(j, "info");
    ProjectInfo info;
    for (const auto& [key, member] : kFields)
        info.*member = r.text(key, "");
    if (!r.has("revisions")) return info;
    const json& list = r.raw("revisions");
    if (!list.is_array()) r.fail("revisions", "expected a list of {id, date, description}");
    if (list.size() > limits::kMaxRevisions)
        r.fail("revisions", std::to_string(list.size()) + " revisions, more than the limit of " +
                                std::to_string(limits::kMaxRevisions));
    for (std::size_t i = 0; i < list.size(); ++i) {
        const JsonReader e(list[i], r.field("revisions") + "[" + std::to_string(i) + "]");
        info.revisions.push_back({e.text("id", ""), e.text("date", ""), e.text("description", "")});
    }
    return info;
}

} // namespace kinstab
