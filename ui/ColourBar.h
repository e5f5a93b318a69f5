// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The γc colour scale: the surface's gradient from 0 (stable) to the largest γc of the grid,
// with values on 1-2-5 ticks. One painter for the 2D map and the bar beside the 3D view.

#include "ui/SurfaceData.h"

#include <QColor>
#include <QWidget>

class QPainter;

namespace kinstab::ui {

// Colour of γc / γmax in [0, 1] (the 3D surface uses the same stops).
QColor gammaColor(double t);
// Colour of a point not computed (a cancelled or running sweep): light grey, unlike any γc.
QColor notComputedColor();
// Top of the colour scale: the grid's largest γc rounded up to a 1-2-5 step (1 if none), the
// same for the 2D map, the 3D view's Y axis and the colour bar, so a colour means one value.
double colourScaleMaximum(const GammaGrid& g);

// Paints the gradient into `bar` and tick labels to its right; the title goes above the bar.
void paintColourBar(QPainter& p, const QRectF& bar, double gMax, const QString& title,
                    bool faded = false);
// Width taken by the bar with its labels at the painter's font.
int colourBarWidth(const QFontMetrics& fm, double gMax);

class ColourBar : public QWidget {
    Q_OBJECT
public:
    explicit ColourBar(QWidget* parent = nullptr);
    void setRange(double gMax, const QString& title);
    void setFaded(bool faded);
    double maximum() const { return m_gMax; }
    QSize sizeHint() const override;
    QSize minimumSizeHint() const override;

protected:
    void paintEvent(QPaintEvent*) override;

private:
    double m_gMax = 1;
    QString m_title = QStringLiteral("γc");
    bool m_faded = false;
};

} // namespace kinstab::ui
