// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Every 2-D chart's value axes tick on 1-2-5 steps (ui/NiceTicks.h): 0.5, 1.0, 1.5 rather than
// 0.96, 1.44, 1.92, whatever range the chart sets later. The range itself is left as the chart
// chose it (a symmetric ±a, a headroom of 10 %); the ticks are the step's multiples inside it,
// labelled with the decimals the step needs.

class QChart;
class QValueAxis;

namespace kinstab::ui {

// The axis keeps 1-2-5 ticks, at most maxTicks intervals, through every later setRange().
void useNiceTicks(QValueAxis* axis, int maxTicks = 6);
// useNiceTicks on each value axis the chart has now.
void useNiceTicks(QChart* chart, int maxTicks = 6);

} // namespace kinstab::ui
