// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Collapse fragility curves of a study (docs/studies.md): per parameter set the fitted lognormal
// curve, its bootstrap bounds (dashed) and the empirical points of the records, in one colour.

#include "core/study/Fragility.h"

#include <vector>

class QChart;

namespace kinstab::ui {

// Replaces the chart's series and axes; the x axis names the sets' intensity measure.
void fillFragilityChart(QChart* chart, const std::vector<Fragility>& sets);

} // namespace kinstab::ui
