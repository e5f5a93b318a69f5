// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The records of a study, each read once. A study runs for hours: a record rewritten, moved or
// deleted meanwhile must not change the rows still to come, so every case of a record uses the
// motion parsed when the study started, and the rows carry the fingerprint of exactly those
// bytes (core/study/StudyFingerprint.h).

#include "core/study/StudySpec.h"

namespace kinstab {

// Reads, hashes and parses every record of the suite, checks that neither it nor any floor
// filter's or level's motion of it is zero throughout, and sets the study's fingerprint.
// Throws StudyError "records: FILE:LINE: message", also beyond kMaxStudySuiteSamples.
void loadStudyRecords(StudySpec& s);

// Reads and hashes every record only (no parsing): the fingerprint against which a results
// file is checked. Throws StudyError "records: FILE: message".
void hashStudyRecords(StudySpec& s);

} // namespace kinstab
