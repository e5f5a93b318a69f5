// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Whether a results file (JSONL rows) is the result of a study file as it is now: a study edited
// after its run must not have the old rows shown or printed as its result. Each row carries its
// case's inputs (record and its scale, mu, t*, floor filter or level, motion, limit, intensity
// measure), and, where the record collapsed the slab, the search limit follows from the row too
// (limit_im / critical_im = max_g / critical_peak). Then each row's fingerprint must be the
// study's (core/study/StudyFingerprint.h), which covers what the rows do not show: the records'
// bytes, the search's step and tolerance, the building.

#include "core/study/StudyRow.h"
#include "core/study/StudySpec.h"

#include <string>
#include <vector>

namespace kinstab {

// "" when rows are the study's cases in order, else the first difference in words
// ("row 3: mu = 0.6, the study file says 0.5"). studyDir: the study file's directory, against
// which a row's relative record label is resolved. spec's records must be hashed
// (hashStudyRecords or loadStudyRecords, core/study/StudyRecords.h).
std::string studyRowsMismatch(const StudySpec& spec, const std::string& studyDir,
                              const std::vector<StudyRow>& rows);

} // namespace kinstab
