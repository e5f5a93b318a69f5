// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Study tab's two tables (ui/StudyTab.h): one row per case (record x parameter set) with
// the record's catalogue numbers beside its critical intensity, and one row per parameter set
// with the statistics of the critical intensity over the suite (count censored, mean, median,
// standard deviation and log-standard deviation: core/study/Fragility.h RecordStatistics)
// beside the fitted fragility.

#include "core/study/Fragility.h"
#include "core/study/StudyRecordMetrics.h"
#include "core/study/StudyRow.h"

#include <vector>

class QTableWidget;
class QWidget;

namespace kinstab::ui {

QTableWidget* makeStudyCaseTable(QWidget* parent);
QTableWidget* makeStudySetTable(QWidget* parent);

// metrics: the suite's records (may be empty, or lack a row's record: its cells stay blank).
void fillStudyCaseTable(QTableWidget* t, const std::vector<StudyRow>& rows,
                        const std::vector<StudyRecordMetrics>& metrics);
void fillStudySetTable(QTableWidget* t, const std::vector<Fragility>& sets);

} // namespace kinstab::ui
