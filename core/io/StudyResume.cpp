// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/io/StudyResume.h"

#include "core/base/InputLimits.h"
#include "core/base/LineReader.h"
#include "core/io/StudyRowJson.h"
#include "core/study/StudyRunner.h"

namespace kinstab {

namespace {

struct Prefix {
    std::size_t rows = 0;
    std::uint64_t bytes = 0;
};

// The complete rows of the shard at the start of the file: the j-th is case k - 1 + j N.
Prefix shardPrefix(const std::string& file, const StudySpec& s, const Shard& shard) {
    Prefix p;
    const std::size_t mine = shardCaseCount(s, shard), cases = studyCaseCount(s);
    try {
        LineReader in(file, limits::kMaxResultsRowBytes);
        std::string line;
        // One pass per row: bounded by the shard's cases.
        while (p.rows < mine && in.next(line) && in.lastLineEnded()) {
            const StudyRow r = parseStudyRow(line);
            if (r.study != s.fingerprint || r.cases != cases ||
                r.index != shard.k - 1 + p.rows * shard.n)
                break;
            ++p.rows;
            p.bytes = in.lineEnd();
        }
    } catch (const LineReadError&) { // what can be read holds the rows that count
    } catch (const StudyRowError&) { // a torn or foreign row ends the shard's rows
    }
    return p;
}

} // namespace

ResumedShard resumeShard(const StudySpec& s, const Shard& shard, const std::string& path) {
    ResumedShard best;
    // One pass per leftover file: bounded by the folder's entries.
    for (const std::string& t : AtomicFileWriter::leftovers(path)) {
        std::unique_ptr<AtomicFileWriter> w = AtomicFileWriter::adopt(path, t);
        if (!w) continue; // in use by a running writer, or not a file of ours
        const Prefix p = shardPrefix(t, s, shard);
        if (p.rows == 0) {
            if (w->size() == 0) w->discard(); // holds nothing: an empty leftover
            continue;
        }
        if (p.rows <= best.done) {
            w->discard(); // fewer rows of the same shard than another leftover
            continue;
        }
        if (best.writer) best.writer->discard();
        w->truncate(p.bytes);
        best = {std::move(w), p.rows};
    }
    return best;
}

} // namespace kinstab
