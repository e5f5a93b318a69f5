// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The catalogue numbers of a study's records (core/excitation/RecordMetrics.h), for the Study
// tab's record table: each record as the suite gives it (the file times its scale), Sa at the
// building's period as the study states it.

#include "core/excitation/RecordMetrics.h"
#include "core/study/StudySpec.h"

#include <optional>
#include <string>
#include <vector>

namespace kinstab {

struct StudyRecordMetrics {
    std::string record; // the label rows carry (StudyRow::record)
    RecordMetrics metrics;
};

// The period of the study's Sa: its intensity measure's when that is Sa, else its first floor
// filter's (the building's period), else none.
std::optional<double> studySaPeriod(const StudySpec& s);

// Every record of the suite, in the suite's order: the motion read by loadStudyRecords when it
// has been, else the file read here. Throws StudyError "records: FILE:LINE: message".
std::vector<StudyRecordMetrics> studyRecordMetrics(const StudySpec& s);

} // namespace kinstab
