// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/assessment/AssessmentJson.h"

#include "core/io/JsonValue.h"

#include <algorithm>
#include <iomanip>
#include <locale>
#include <sstream>

namespace kinstab {

namespace {

nlohmann::json comparisonJson(const Comparison& x) {
    return {{"intensity", x.intensity},
            {"unit", x.unit},
            {"demand_name", x.demandName},
            {"demand", x.demand},
            {"capacity_name", x.capacityName},
            {"capacity", orNull(x.capacity)},
            {"search_limit", x.searchLimit},
            {"margin", orNull(x.margin)},
            {"margin_at_least", x.margin ? nlohmann::json() : nlohmann::json(x.orderingMargin())},
            {"holds", x.holds()}};
}

nlohmann::json checkJson(const Check& c) {
    nlohmann::json j = {{"id", c.id},
                        {"basis", checkBasisName(c.basis)},
                        {"code", c.code},
                        {"code_title", c.codeTitle},
                        {"level", checkLevelName(c.level)},
                        {"model", c.model},
                        {"excitation", c.excitation}};
    j.update(comparisonJson(c.governing())); // the check's own figures: its governing comparison
    j["holds"] = c.holds;
    j["verdict"] = c.verdict;
    nlohmann::json all = nlohmann::json::array();
    for (const Comparison& x : c.comparisons)
        all.push_back(comparisonJson(x));
    j["comparisons"] = all;
    return j;
}

} // namespace

nlohmann::json assessmentJson(const Assessment& a) {
    nlohmann::json checks = nlohmann::json::array();
    for (const Check& c : a.checks)
        checks.push_back(checkJson(c));
    nlohmann::json governing;
    if (const Check* c = a.governingCheck())
        governing = {{"id", c->id},
                     {"margin", orNull(c->governing().margin)},
                     {"margin_at_least", c->governing().margin
                                             ? nlohmann::json()
                                             : nlohmann::json(c->governing().orderingMargin())},
                     {"holds", c->holds},
                     {"verdict", c->verdict},
                     {"reason", a.governingReason}};
    return {{"checks", checks}, {"governing", governing}, {"notes", a.notes}};
}

std::string assessmentTable(const Assessment& a) {
    std::ostringstream s;
    s.imbue(std::locale::classic());
    // Block ids carry the block's name: the column grows to the longest id.
    int width = 24;
    for (const Check& c : a.checks)
        width = std::max(width, static_cast<int>(c.id.size()) + 2);
    s << std::left << std::setw(width) << "check" << std::setw(10) << "demand" << std::setw(10)
      << "capacity" << std::setw(9) << "margin"
      << "verdict\n";
    for (const Check& c : a.checks) {
        const Comparison& x = c.governing();
        s << std::setw(width) << c.id << std::setw(10) << quantityText(x, x.demand) << std::setw(10)
          << (x.capacity ? quantityText(x, *x.capacity) : "none") << std::setw(9) << marginText(x)
          << c.verdict << "\n";
    }
    if (const Check* c = a.governingCheck())
        s << "\ngoverning: " << c->id << ", margin " << marginText(c->governing()) << ", "
          << c->verdict << "\n  " << a.governingReason << "\n";
    for (const std::string& n : a.notes)
        s << "note: " << n << "\n";
    return s.str();
}

} // namespace kinstab
