// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/StudyResults.h"

#include "core/base/InputLimits.h"
#include "core/base/LineReader.h"
#include "core/base/TextInput.h"
#include "core/io/ShardPool.h"
#include "core/study/StudySpec.h"

#include <sys/stat.h>

#include <memory>
#include <queue>
#include <set>
#include <utility>

namespace kinstab {

namespace {

// A results file is at most one row of ~1 kB (long record paths) per case of the largest study.
constexpr std::uintmax_t kMaxResultsBytes = 1024ull * kMaxStudyCases;

std::unique_ptr<LineReader> openResults(const std::string& path, std::size_t chunk) {
    struct stat st {};
    if (::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode) &&
        static_cast<std::uintmax_t>(st.st_size) > kMaxResultsBytes)
        throw StudyRowError(path + ": larger than the limit of " +
                            std::to_string(kMaxResultsBytes) + " bytes");
    try {
        return std::make_unique<LineReader>(path, limits::kMaxResultsRowBytes, chunk);
    } catch (const LineReadError& e) {
        throw StudyRowError(path + ": " + e.what());
    }
}

} // namespace

StudyRowReader::StudyRowReader(const std::string& path, std::size_t chunk)
    : path_(path), file_(openResults(path, chunk)) {}

StudyRowReader::~StudyRowReader() = default;

bool StudyRowReader::next() {
    const std::size_t before = line_.row.index;
    try {
        if (!file_->next(line_.text)) return false;
    } catch (const LineReadError& e) {
        throw StudyRowError(path_ + ": " + e.what());
    }
    const long number = file_->lineNumber();
    line_.where = path_ + ":" + std::to_string(number);
    if (number == 1) line_.text = std::string(withoutBom(line_.text));
    try {
        line_.row = parseStudyRow(line_.text);
    } catch (const StudyRowError& e) {
        throw StudyRowError(line_.where + ": " + e.what());
    }
    // Of another study before out of order: rows of two studies are named as such.
    if (number == 1) first_ = line_;
    requireSameStudy(line_, first_);
    if (number > 1 && line_.row.index == before)
        throw StudyRowError(line_.where + ": case " + std::to_string(before) + " appears twice");
    if (number > 1 && line_.row.index < before)
        throw StudyRowError(line_.where + ": case " + std::to_string(line_.row.index) +
                            " is not after case " + std::to_string(before) +
                            ": a shard is in case order");
    return true;
}

LineReader& StudyRowReader::file() {
    return *file_;
}

void requireSameStudy(const StudyLine& l, const StudyLine& first) {
    const StudyRow &a = l.row, &b = first.row;
    if (a.study == b.study && a.cases == b.cases && a.measure == b.measure) return;
    throw StudyRowError(l.where + ": a row of another study than " + first.where + "'s: study " +
                        a.study + " of " + std::to_string(a.cases) + " cases (" + a.measure +
                        "), not " + b.study + " of " + std::to_string(b.cases) + " cases (" +
                        b.measure + "); rows of two different studies are not one result");
}

namespace {

// Calls onRow for every row of the file, in case order and of line 1's study (StudyRowReader),
// each parameter set's rows together.
template <class F> void forEachRow(const std::string& path, F&& onRow) {
    StudyRowReader file(path);
    bool any = false;
    std::set<std::size_t> done; // sets already passed: each set's rows stand together
    std::size_t set = 0;
    // One pass per line: bounded by the file's lines (at most its bytes).
    while (file.next()) {
        const StudyLine& l = file.line();
        any = true;
        if (l.row.set != set) {
            done.insert(set);
            set = l.row.set;
        }
        if (done.count(l.row.set))
            throw StudyRowError(l.where + ": a row of parameter set " + std::to_string(l.row.set) +
                                " after rows of another set: a results file keeps each set's "
                                "rows together (merge the shards with kinstab-cli merge)");
        onRow(l);
    }
    if (!any) throw StudyRowError(path + ": no rows");
}

} // namespace

std::vector<StudyRow> readStudyRows(const std::string& path, std::string* text) {
    std::vector<StudyRow> rows;
    std::string kept;
    forEachRow(path, [&](const StudyLine& l) {
        rows.push_back(l.row);
        if (text) kept += l.text + "\n";
    });
    if (text) *text = std::move(kept);
    return rows;
}

void forEachStudySet(const std::string& path,
                     const std::function<void(std::vector<StudyRow>&&)>& onSet) {
    std::vector<StudyRow> set;
    forEachRow(path, [&](const StudyLine& l) {
        if (!set.empty() && set.front().set != l.row.set) onSet(std::exchange(set, {}));
        set.push_back(l.row);
    });
    onSet(std::move(set));
}

void mergeStudyShards(const std::vector<std::string>& paths,
                      const std::function<void(std::string_view)>& sink) {
    ShardPool shards(paths);
    // The shards whose line in hand comes next: smallest case first, then the shard named first.
    using Entry = std::pair<std::size_t, std::size_t>; // case index, shard
    std::priority_queue<Entry, std::vector<Entry>, std::greater<>> heap;
    for (std::size_t k = 0; k < paths.size(); ++k)
        if (shards.next(k)) heap.push({shards.line(k).row.index, k});
    if (heap.empty()) throw StudyRowError("no rows in the shards");
    const StudyLine first = shards.line(heap.top().second);
    std::size_t expected = 0;
    std::string block;
    // Each pass takes one line off the heap: bounded by the lines of the shards.
    while (!heap.empty()) {
        const auto [index, k] = heap.top();
        heap.pop();
        const StudyLine& l = shards.line(k);
        requireSameStudy(l, first);
        if (index < expected)
            throw StudyRowError(l.where + ": case " + std::to_string(index) + " appears twice");
        if (index > expected) {
            // Case `expected` is in no line in hand; before saying it is in none of the shards,
            // the rest of every shard is read: a shard out of case order is named at its line.
            shards.readToEnd();
            break;
        }
        block += l.text;
        block += '\n';
        ++expected;
        if (block.size() >= (1u << 20)) {
            sink(block);
            block.clear();
        }
        if (shards.next(k)) heap.push({shards.line(k).row.index, k});
    }
    if (expected != first.row.cases)
        throw StudyRowError("case " + std::to_string(expected) + " of " +
                            std::to_string(first.row.cases) + " is in none of the shards");
    sink(block);
}

} // namespace kinstab
