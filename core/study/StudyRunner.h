// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Runs the cases of a study (or of one shard of it) on worker threads and hands the rows on in
// case order, a block at a time, so that memory does not grow with the number of cases and the
// output is the same rows whatever the number of threads. The rows are values: who writes them
// as text (core/io/StudyRowJson.h) or keeps them is the caller's choice.

#include "core/study/StudyCase.h"
#include "core/study/StudyRow.h"
#include "core/sweep/SweepControl.h"

#include <functional>
#include <string>
#include <vector>

namespace kinstab {

// One case: the critical intensity of the record for the case's slab and floor. The study's
// records must have been read (loadStudyRecords, core/study/StudyRecords.h): a case never reads
// a file, so a record changed during the study cannot change its rows.
StudyRow runStudyCase(const StudySpec& s, const StudyCase& c);
// The ground motion of a case: the record as read, or with every sample's sign flipped.
Accelerogram caseGround(const Accelerogram& record, bool inverted);

struct StudyRunOptions {
    Shard shard;
    unsigned threads = 1;
    SweepControl* control = nullptr; // cancel (stops within one case per thread); progress
    std::size_t done = 0; // the shard's first cases already written (study --resume): skipped
};

// The number of cases of shard `shard` of the study.
std::size_t shardCaseCount(const StudySpec& s, const Shard& shard);

// Receives each finished block of rows, in case order.
using StudyRowSink = std::function<void(const std::vector<StudyRow>&)>;

// Calls sink with the rows of each finished block of cases, in case order, from the shard's
// case `done` on. Returns the number of rows handed on; fewer than the shard's cases less `done`
// only when cancelled.
std::size_t runStudy(const StudySpec& s, const StudyRunOptions& options, const StudyRowSink& sink);
// Every row of the run at once, for those that keep them all (the GUI, the report, Python): as
// many rows as runStudy hands on.
std::vector<StudyRow> runStudyRows(const StudySpec& s, const StudyRunOptions& options);

} // namespace kinstab
