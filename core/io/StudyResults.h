// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Reading study results (JSONL) back: the rows of one file, and the merge of shards into the
// file an unsharded run writes - the same rows, in case order, the same bytes. The merge streams:
// each shard is in case order (as kinstab-cli study writes it), so a k-way merge holds one line
// per shard, and its memory does not grow with the number of rows.

#include "core/io/StudyRowJson.h"

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace kinstab {

class LineReader;

struct StudyLine {
    std::string text;
    StudyRow row;
    std::string where; // FILE:LINE
};

// The rows of one results file, one line in hand: each line at most limits::kMaxResultsRowBytes
// (core/base/InputLimits.h), a read error told apart from the end of the file, every row
// validated (parseStudyRow), of line 1's study, and in case order with no case twice. Throws
// StudyRowError naming FILE or FILE:LINE.
class StudyRowReader {
public:
    explicit StudyRowReader(const std::string& path, std::size_t chunk = 1 << 16);
    ~StudyRowReader();
    bool next(); // false at the end of the file
    const StudyLine& line() const { return line_; }
    LineReader& file();

private:
    std::string path_;
    std::unique_ptr<LineReader> file_;
    StudyLine line_, first_;
};

// Throws StudyRowError naming both lines and both fingerprints when l is of another study
// (fingerprint, size or intensity measure) than first.
void requireSameStudy(const StudyLine& l, const StudyLine& first);

// Throws StudyRowError "FILE:LINE: message" for a line that is not a study row, a row of another
// study (fingerprint, size or intensity measure) than the first, a case given twice or out of
// case order, or a parameter set's rows apart. Blank lines are not allowed either: a study file
// is written whole.
// text: the file's text as read, when asked (one read for rows kept and shown).
std::vector<StudyRow> readStudyRows(const std::string& path, std::string* text = nullptr);

// Hands onSet the rows of one results file a parameter set at a time (the rows of a set are
// neighbours in case order), holding one set's rows: the fragility of a study of millions of
// cases takes the memory of its largest set. Throws StudyRowError "FILE:LINE: message" as
// readStudyRows does, and for a row out of case order (a study or merge writes them in order).
void forEachStudySet(const std::string& path,
                     const std::function<void(std::vector<StudyRow>&&)>& onSet);

// Hands sink the lines of the shards in case order, a block at a time. Throws StudyRowError
// naming the file and line of a row that is broken, repeated, out of case order in its shard or
// of another study (both fingerprints named), and the first missing case when the shards do not
// cover the study; what sink has received by then is not the whole study. Any number of shards:
// those beyond the open-file limit are read with their descriptors released in turn
// (core/io/ShardPool.h).
void mergeStudyShards(const std::vector<std::string>& paths,
                      const std::function<void(std::string_view)>& sink);

} // namespace kinstab
