// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A plain line plot for the report: a few named curves on linear axes with a legend (the
// record's time histories and Fourier spectra, Figs. 25-27 style).

#include <QColor>
#include <QList>
#include <QPainter>
#include <QPointF>
#include <QRectF>
#include <QString>

#include <vector>

namespace kinstab::report {

struct Curve {
    QList<QPointF> points;
    QColor colour;
    QString label;
    double width = 0.15; // pen width in figure units
};

struct CurvePlot {
    std::vector<Curve> curves;
    double xlo = 0, xhi = 1, ylo = 0, yhi = 1;
    QString xLabel, yLabel;
};

void paintCurves(QPainter& p, const QRectF& area, const CurvePlot& plot);

} // namespace kinstab::report
