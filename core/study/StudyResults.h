// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Reading study results (JSONL) back: the rows of one file, and the merge of shards into the
// file an unsharded run writes - the same rows, in case order, the same bytes.

#include "core/study/StudyRow.h"

#include <string>
#include <vector>

namespace kinstab {

// Throws StudyRowError "FILE:LINE: message" for a line that is not a study row, a row of another
// study (size or intensity measure) than the first, or a case given twice. Blank lines are not
// allowed either: a study file is written whole.
std::vector<StudyRow> readStudyRows(const std::string& path);

// The lines of the shards in case order. Throws StudyRowError naming the file and line of a row
// that is broken, repeated or belongs to a study of another size, and the first missing case
// when the shards do not cover the study.
std::string mergeStudyShards(const std::vector<std::string>& paths);

} // namespace kinstab
