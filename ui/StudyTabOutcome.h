// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// What a Study tab job (a run, or results read back) hands to the GUI thread (ui/StudyTab.h).

#include "core/study/Fragility.h"
#include "core/study/StudyRecordMetrics.h"

#include <QString>

#include <string>
#include <vector>

namespace kinstab {
class SweepControl;
}

namespace kinstab::ui {

struct StudyOutcome {
    std::string rows, error;
    bool cancelled = false;
    std::vector<StudyRow> parsed;
    std::vector<Fragility> fragility;
    std::vector<StudyRecordMetrics> metrics; // the suite's records' catalogue numbers
    std::string spec;                        // studyJson() of the fields the results are for
    QString file;                            // the results file read ("": a run)
    QString notice;                          // why a results file is not shown
};

// The job that runs the study text json: every case, then the fragility (ui/StudyTab.cpp).
StudyOutcome runStudyJob(const std::string& json, SweepControl* control);
// The job that reads a results file back, checks it is the study file's and fits the fragility
// (ui/StudyTabProject.cpp). Both run off the GUI thread.
StudyOutcome readStudyResults(const QString& specPath, const QString& rowsPath);

} // namespace kinstab::ui
