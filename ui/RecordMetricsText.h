// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A record's catalogue numbers (core/excitation/RecordMetrics.h) as the Records tab and the
// Study tab show them: one line of text, and the cells of a table row, with their headers.

#include "core/excitation/RecordMetrics.h"

#include <QString>
#include <QStringList>

namespace kinstab::ui {

// "PGA 0.281 g · PGV 30.9 cm/s · PGD 8.66 cm · Arias 1.54 m/s · D5–95 24.2 s · Tm 0.579 s ·
// Sa(1 s, 5 %) 0.473 g"
QString recordMetricsLine(const RecordMetrics& m);
// The table's column headers and a row's cells, in the same order ("–" where a number does not
// exist: the duration of a record of zeros).
QStringList recordMetricsHeaders();
QStringList recordMetricsCells(const RecordMetrics& m);
// What each number is and how it is computed (the headers' tooltip).
QString recordMetricsToolTip();

} // namespace kinstab::ui
