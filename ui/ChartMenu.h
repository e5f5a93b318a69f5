// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Right-click on any 2-D chart of the application: "Save image…" (PNG or SVG, ui/ChartExport.h,
// the dialog in the open project's folder) and "Copy image" (to the clipboard). One event
// filter on the application covers every chart, also those a view creates later.

class QChartView;
class QMenu;

namespace kinstab::ui {

// Installs the filter once per application.
void installChartMenus();
// The menu for view (for tests: its actions are named saveChartImage and copyChartImage).
QMenu* chartMenu(QChartView* view);

} // namespace kinstab::ui
