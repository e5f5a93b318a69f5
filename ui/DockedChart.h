// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The frame the docked charts share (slice, histories, A_crit(f)): the title above and the
// legend below the plot, each wrapping onto more lines in a narrow dock (never elided),
// antialiasing, and a small minimum size so that their docks can shrink.

#include <QChartView>
#include <QLineSeries>

#include <initializer_list>

namespace kinstab::ui {

// After the chart's margins are set: the title's and the legend's room is added to them.
void installDockedChart(QChartView* view, QChart* chart, const QString& title);
// A line series with its legend name and pen.
QLineSeries* chartLine(const QString& name, const QColor& color, qreal width,
                       Qt::PenStyle style = Qt::SolidLine);
// Keeps series out of the legend (the unnamed second half of a ± pair).
void hideFromLegend(QChart* chart, std::initializer_list<QAbstractSeries*> series);

} // namespace kinstab::ui
