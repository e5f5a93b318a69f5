// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// A 2D plot frame for the report's figures: linear axes with round ticks, mapped into a
// rectangle, drawn as vector line art and text. Fonts and pens scale with the figure width so
// a figure reads the same on a 300 dpi page and in a small test image.

#include <QFont>
#include <QPainter>
#include <QRectF>
#include <QString>

#include <vector>

namespace kinstab::report {

// Round tick values covering [lo, hi] (about `target` of them, steps 1, 2, 2.5 or 5 × 10^k).
std::vector<double> niceTicks(double lo, double hi, int target = 6);
QString tickLabel(double v, double step);

// Sizes relative to a figure's width: unit() is 1/100 of it.
struct FigureScale {
    double width = 1000;
    double unit() const { return width / 100.0; }
    QFont font(double size, bool bold = false) const; // size in units
    QPen pen(const QColor& c, double widthUnits) const;
};

struct LegendEntry {
    QString label;
    QColor colour;
    Qt::PenStyle style = Qt::SolidLine;
};

// A boxed legend with its top-left corner at `at` (or its top-right when alignRight).
void drawLegend(QPainter& p, const FigureScale& sc, const QPointF& at,
                const std::vector<LegendEntry>& entries, bool alignRight = false);

// The same entries in rows of `columns` across the strip `area` (below a plot, outside its data);
// legendRowsHeight gives the height the strip needs.
double legendRowsHeight(const FigureScale& sc, std::size_t entries, int columns);
void drawLegendRows(QPainter& p, const FigureScale& sc, const QRectF& area,
                    const std::vector<LegendEntry>& entries, int columns);

// A code ratio's legend entry ("UBC 1976: 0.230"), dashed as its line.
LegendEntry codeRatioEntry(const QString& code, double ratio, const QColor& colour);

class PlotFrame {
public:
    // area: the whole figure; the plot rectangle leaves room for the labels around it.
    PlotFrame(const QRectF& area, double xlo, double xhi, double ylo, double yhi,
              double rightRoom = 0);

    QRectF plot() const { return plot_; }
    QPointF map(double x, double y) const;
    double mapX(double x) const;
    double mapY(double y) const;
    const FigureScale& scale() const { return scale_; }

    void drawAxes(QPainter& p, const QString& xLabel, const QString& yLabel) const;
    // A vertical line across the plot at x (pen 0.3 units) when x lies on it; false when not.
    bool verticalLine(QPainter& p, double x, const QColor& c, Qt::PenStyle style) const;

private:
    QRectF plot_;
    double xlo_, xhi_, ylo_, yhi_;
    FigureScale scale_;
};

} // namespace kinstab::report
