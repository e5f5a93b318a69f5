// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Runs the cases of a study (or of one shard of it) on worker threads and hands the rows on in
// case order, a block at a time, so that memory does not grow with the number of cases and the
// output is the same bytes whatever the number of threads.

#include "core/study/StudyCase.h"
#include "core/study/StudyRow.h"
#include "core/sweep/SweepControl.h"

#include <functional>
#include <string>

namespace kinstab {

// Reads every record of the suite once (and through each floor filter), so that a broken file
// is found before any case runs: throws StudyError "records: FILE:LINE: message".
void checkStudyRecords(const StudySpec& s);

// One case: the critical intensity of the record for the case's slab and floor.
StudyRow runStudyCase(const StudySpec& s, const StudyCase& c);

struct StudyRunOptions {
    Shard shard;
    unsigned threads = 1;
    SweepControl* control = nullptr; // cancel (stops within one case per thread); progress
};

// Calls sink with the JSONL text ("...\n" per row) of each finished block of cases, in case
// order. Returns the number of rows written; fewer than the shard's cases only when cancelled.
std::size_t runStudy(const StudySpec& s, const StudyRunOptions& options,
                     const std::function<void(const std::string&)>& sink);

} // namespace kinstab
