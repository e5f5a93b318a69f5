// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/DockedChart.h"

#include <QLegendMarker>

namespace kinstab::ui {

void installDockedChart(QChartView* view, QChart* chart, const QString& title,
                        Qt::Alignment legendSide) {
    chart->legend()->setAlignment(legendSide);
    chart->setTitle(title);
    view->setChart(chart);
    view->setRenderHint(QPainter::Antialiasing);
    view->setMinimumSize(240, 160);
}

QLineSeries* chartLine(const QString& name, const QColor& color, qreal width, Qt::PenStyle style) {
    auto* s = new QLineSeries;
    s->setName(name);
    s->setPen(QPen(color, width, style));
    return s;
}

void hideFromLegend(QChart* chart, std::initializer_list<QAbstractSeries*> series) {
    for (QAbstractSeries* s : series)
        for (QLegendMarker* marker : chart->legend()->markers(s))
            marker->setVisible(false);
}

} // namespace kinstab::ui
