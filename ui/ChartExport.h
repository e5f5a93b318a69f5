// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// Writes a chart as PNG (raster, 2x) or SVG (vector, via QSvgGenerator), by file suffix.

#include <QString>

class QChartView;

namespace kinstab::ui {

// Empty on success, else a message naming the file.
QString exportChart(QChartView* view, const QString& path);

} // namespace kinstab::ui
