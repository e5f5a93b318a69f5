// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/StudyResults.h"

#include "core/base/TextInput.h"
#include "core/study/StudySpec.h"

#include <map>
#include <set>
#include <sstream>

namespace kinstab {

namespace {

// A results file is at most one row of ~1 kB (long record paths) per case of the largest study.
constexpr std::uintmax_t kMaxResultsBytes = 1024ull * kMaxStudyCases;

struct Line {
    std::string text;
    StudyRow row;
    std::string where; // FILE:LINE
};

// Calls f(Line) for every line of the file; throws StudyRowError naming FILE:LINE.
template <class F> void forEachRow(const std::string& path, F&& f) {
    const FileText file = readTextFile(path, kMaxResultsBytes);
    if (!file.error.empty()) throw StudyRowError(path + ": " + file.error);
    std::istringstream in{std::string(withoutBom(file.text))};
    std::string text;
    for (long n = 1; std::getline(in, text); ++n) {
        const std::string where = path + ":" + std::to_string(n);
        try {
            f(Line{text, parseStudyRow(text), where});
        } catch (const StudyRowError& e) {
            throw StudyRowError(where + ": " + e.what());
        }
    }
}

} // namespace

std::vector<StudyRow> readStudyRows(const std::string& path) {
    std::vector<StudyRow> rows;
    std::set<std::size_t> seen;
    forEachRow(path, [&](Line l) {
        // One study's rows: the same size and intensity measure, each case once.
        if (!rows.empty() &&
            (l.row.cases != rows.front().cases || l.row.measure != rows.front().measure))
            throw StudyRowError(l.where + ": a row of another study than line 1's");
        if (!seen.insert(l.row.index).second)
            throw StudyRowError(l.where + ": case " + std::to_string(l.row.index) +
                                " appears twice");
        rows.push_back(std::move(l.row));
    });
    if (rows.empty()) throw StudyRowError(path + ": no rows");
    return rows;
}

std::string mergeStudyShards(const std::vector<std::string>& paths) {
    std::map<std::size_t, std::string> lines;
    std::size_t cases = 0;
    std::string first;
    for (const std::string& path : paths)
        forEachRow(path, [&](const Line& l) {
            if (first.empty()) {
                cases = l.row.cases;
                first = l.where;
            }
            if (l.row.cases != cases)
                throw StudyRowError(l.where + ": a study of " + std::to_string(l.row.cases) +
                                    " cases, but " + first + " is of " + std::to_string(cases));
            if (!lines.emplace(l.row.index, l.text + "\n").second)
                throw StudyRowError(l.where + ": case " + std::to_string(l.row.index) +
                                    " appears twice");
        });
    if (lines.empty()) throw StudyRowError("no rows in the shards");
    std::size_t expected = 0;
    std::string out;
    for (const auto& [index, text] : lines) {
        if (index != expected) break;
        out += text;
        ++expected;
    }
    if (expected != cases)
        throw StudyRowError("case " + std::to_string(expected) + " of " + std::to_string(cases) +
                            " is in none of the shards");
    return out;
}

} // namespace kinstab
