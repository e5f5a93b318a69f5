// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// study --resume (docs/studies.md, "Resuming a shard"): a shard run continues from the complete
// rows of the temporary file that an interrupted run of the same shard left beside its output
// (kill -9, a node failure, or SIGTERM/Ctrl+C of a --resume run), instead of from its first case.
// A row counts only when it is a whole line, a valid row of this study (its fingerprint: the
// same parameters and record bytes) and the shard's next case; the file is cut after the last
// such row (a row torn by the kill is dropped).

#include "core/io/AtomicFile.h"
#include "core/study/StudyCase.h"
#include "core/study/StudySpec.h"

#include <cstddef>
#include <memory>
#include <string>

namespace kinstab {

struct ResumedShard {
    std::unique_ptr<AtomicFileWriter> writer; // kept on interruption; none: nothing to resume
    std::size_t done = 0;                     // the shard's cases already in it
};

// Of the temporary files left beside path, takes the one with the most complete rows of the
// study's shard (s's records read: its fingerprint set) and cuts it after them; removes the
// others that hold rows of it or nothing at all. Leaves alone files in use by a running writer
// and files of other studies or shards.
ResumedShard resumeShard(const StudySpec& s, const Shard& shard, const std::string& path);

} // namespace kinstab
