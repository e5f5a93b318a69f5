// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The Friction tab's chart parts (ui/FrictionPanel.h): its units per unit system (the paper's
// tests are kept in kip, psi and in), one colour per contact pressure, axes on 1-2-5 ticks and
// the two chart views.

#include "ui/Units.h"

#include <QColor>
#include <QList>
#include <QString>

class QAbstractSeries;
class QChart;
class QChartView;
class QValueAxis;

namespace kinstab::ui::friction {

// The shown units per unit system: shown per kip, psi, in, in² and their symbols.
struct ShownUnits {
    double force, pressure, length, area;
    QString f, p, l, a;
};
ShownUnits shownUnits(UnitSystem s);

QColor cpColor(int i); // the i-th contact pressure's colour, its fit and its test points
QValueAxis* axis(const QString& title, double lo, double hi);
// Attaches the series to fresh axes (the chart owns everything).
void resetChart(QChart* chart, const QList<QAbstractSeries*>& series, QValueAxis* x, QValueAxis* y);
QChartView* makeChartView(const QString& title);

} // namespace kinstab::ui::friction
