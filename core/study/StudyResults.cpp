// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/study/StudyResults.h"

#include "core/base/TextInput.h"
#include "core/study/StudySpec.h"

#include <filesystem>
#include <fstream>
#include <memory>
#include <queue>
#include <set>
#include <sstream>
#include <utility>

namespace kinstab {

namespace {

// A results file is at most one row of ~1 kB (long record paths) per case of the largest study.
constexpr std::uintmax_t kMaxResultsBytes = 1024ull * kMaxStudyCases;

struct Line {
    std::string text;
    StudyRow row;
    std::string where; // FILE:LINE
};

// Calls f(Line) for every line of the text of file `path`; throws StudyRowError naming
// FILE:LINE.
template <class F> void forEachRow(std::string_view text, const std::string& path, F&& f) {
    std::istringstream in{std::string(withoutBom(text))};
    std::string line;
    for (long n = 1; std::getline(in, line); ++n) {
        const std::string where = path + ":" + std::to_string(n);
        try {
            f(Line{line, parseStudyRow(line), where});
        } catch (const StudyRowError& e) {
            throw StudyRowError(where + ": " + e.what());
        }
    }
}

} // namespace

std::vector<StudyRow> readStudyRows(const std::string& path, std::string* text) {
    FileText file = readTextFile(path, kMaxResultsBytes);
    if (!file.error.empty()) throw StudyRowError(path + ": " + file.error);
    std::vector<StudyRow> rows;
    std::set<std::size_t> seen, doneSets;
    forEachRow(file.text, path, [&](Line l) {
        if (!rows.empty() && rows.back().set != l.row.set) doneSets.insert(rows.back().set);
        if (doneSets.count(l.row.set))
            throw StudyRowError(l.where + ": a row of parameter set " + std::to_string(l.row.set) +
                                " after rows of another set: a results file keeps each set's "
                                "rows together (merge the shards with kinstab-cli merge)");
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
    if (text) *text = std::move(file.text);
    return rows;
}

namespace {

// One shard being merged: its file and the line in hand.
class ShardReader {
public:
    explicit ShardReader(const std::string& path) : path_(path), in_(path, std::ios::binary) {
        std::error_code ec;
        const auto size = std::filesystem::file_size(path, ec);
        if (!in_ || ec) throw StudyRowError(path + ": cannot be read");
        if (size > kMaxResultsBytes)
            throw StudyRowError(path + ": larger than the limit of " +
                                std::to_string(kMaxResultsBytes) + " bytes");
    }
    // The next line; false at the end of the file. Throws StudyRowError naming FILE:LINE.
    bool next() {
        if (!std::getline(in_, line_.text)) {
            // The end of the file, or a read that failed (an I/O error, memory): never the same.
            if (in_.bad() || !in_.eof())
                throw StudyRowError(path_ + ":" + std::to_string(number_ + 1) +
                                    ": cannot be read (a read error, not the end of the file)");
            return false;
        }
        ++number_;
        line_.where = path_ + ":" + std::to_string(number_);
        if (number_ == 1) line_.text = std::string(withoutBom(line_.text));
        const std::size_t before = line_.row.index;
        try {
            line_.row = parseStudyRow(line_.text);
        } catch (const StudyRowError& e) {
            throw StudyRowError(line_.where + ": " + e.what());
        }
        if (number_ > 1 && line_.row.index == before)
            throw StudyRowError(line_.where + ": case " + std::to_string(before) +
                                " appears twice");
        if (number_ > 1 && line_.row.index < before)
            throw StudyRowError(line_.where + ": case " + std::to_string(line_.row.index) +
                                " is not after case " + std::to_string(before) +
                                ": a shard is in case order");
        return true;
    }
    const Line& line() const { return line_; }

private:
    std::string path_;
    std::ifstream in_;
    Line line_;
    long number_ = 0;
};

} // namespace

void forEachStudySet(const std::string& path,
                     const std::function<void(std::vector<StudyRow>&&)>& onSet) {
    ShardReader file(path);
    std::vector<StudyRow> set;
    std::set<std::size_t> done; // sets already handed on: each set's rows stand together
    std::size_t cases = 0;
    std::string measure;
    bool any = false;
    while (file.next()) {
        const Line& l = file.line();
        if (!any) {
            cases = l.row.cases;
            measure = l.row.measure;
            any = true;
        } else if (l.row.cases != cases || l.row.measure != measure) {
            throw StudyRowError(l.where + ": a row of another study than line 1's");
        }
        if (!set.empty() && set.front().set != l.row.set) {
            done.insert(set.front().set);
            onSet(std::exchange(set, {}));
        }
        if (done.count(l.row.set))
            throw StudyRowError(l.where + ": a row of parameter set " + std::to_string(l.row.set) +
                                " after rows of another set: a results file keeps each set's "
                                "rows together (merge the shards with kinstab-cli merge)");
        set.push_back(l.row);
    }
    if (!any) throw StudyRowError(path + ": no rows");
    onSet(std::move(set));
}

void mergeStudyShards(const std::vector<std::string>& paths,
                      const std::function<void(std::string_view)>& sink) {
    std::vector<std::unique_ptr<ShardReader>> shards;
    // The shards whose line in hand comes next: smallest case first, then the shard named first.
    using Entry = std::pair<std::size_t, std::size_t>; // case index, shard
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> heap;
    for (const std::string& path : paths) {
        shards.push_back(std::make_unique<ShardReader>(path));
        if (shards.back()->next()) heap.push({shards.back()->line().row.index, shards.size() - 1});
    }
    if (heap.empty()) throw StudyRowError("no rows in the shards");
    const Line& first = shards[heap.top().second]->line();
    const std::size_t cases = first.row.cases;
    const std::string firstWhere = first.where;
    std::size_t expected = 0;
    std::string block;
    // Each pass takes one line off the heap: bounded by the lines of the shards.
    while (!heap.empty()) {
        const auto [index, k] = heap.top();
        heap.pop();
        const Line& l = shards[k]->line();
        if (l.row.cases != cases)
            throw StudyRowError(l.where + ": a study of " + std::to_string(l.row.cases) +
                                " cases, but " + firstWhere + " is of " + std::to_string(cases));
        if (index < expected)
            throw StudyRowError(l.where + ": case " + std::to_string(index) + " appears twice");
        if (index > expected) break; // case `expected` is in none of the shards
        block += l.text;
        block += '\n';
        ++expected;
        if (block.size() >= (1u << 20)) {
            sink(block);
            block.clear();
        }
        if (shards[k]->next()) heap.push({shards[k]->line().row.index, k});
    }
    if (expected != cases)
        throw StudyRowError("case " + std::to_string(expected) + " of " + std::to_string(cases) +
                            " is in none of the shards");
    sink(block);
}

} // namespace kinstab
