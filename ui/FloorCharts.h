// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The charts of the Floors view (ui/FloorsView.h), also drawn into the report:
//  - the height profile of the peak floor acceleration: the model's for the record, the SDOF
//    floor filter's at the roof, the ASCE 7-22 and EN 1998-1 demands;
//  - the critical PGA per level, beside the record's own PGA;
//  - one level's motion (and the ground's) with the slab's relative displacement under it.

#include "core/building/FloorAnalysis.h"

#include <QChart>

namespace kinstab::ui {

// heights: level heights above the base, in the building's unit (unitName for the axis).
void fillProfileChart(QChart* chart, const FloorAnalysis& a, const std::vector<double>& heights,
                      const QString& unitName);
void fillCriticalChart(QChart* chart, const FloorAnalysis& a, const std::vector<double>& heights,
                       const QString& unitName);

// The slab on level `level` (1-based) under that level's motion as recorded: the motion and
// the ground (g) against time, the slab's relative displacement delta / (d/2) on a second axis.
// Returns the run's outcome in words ("collapsed at 5.43 s", "stable").
QString fillLevelChart(QChart* chart, const FloorAnalysis& a, const Accelerogram& ground,
                       const Slab1DCase& slab, int level);

void clearChart(QChart* chart);

} // namespace kinstab::ui
