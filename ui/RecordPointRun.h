// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The record run as a PointRun for HistoryChart: delta(tau), the scaled motion under the slab,
// the +-mu slip thresholds and the fitted envelope (Fig. 27) scaled like the motion.

#include "core/check/RecordAnalysis.h"
#include "ui/PointRun.h"

namespace kinstab::ui {

// events: a.run's, as the recorder passed to analyseRecord kept them (SlabEventLog).
PointRun recordPointRun(const Slab1DCase& c, const RecordAnalysis& a,
                        const std::vector<SlabEvent>& events);

} // namespace kinstab::ui
