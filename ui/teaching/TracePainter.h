// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The traces under the drawing: a(tau) with the +-mu band and the envelope, and delta(tau)
// coloured by state with the bearing limit; a cursor at the current tau. Already-played time
// is drawn in full colour, what is still to come in grey.

#include "ui/teaching/TeachingRun.h"

#include <QRectF>

class QFont;
class QPainter;

namespace kinstab::ui {

struct TraceLayout {
    QRectF accelPlot; // plotting areas (inside the axes)
    QRectF deltaPlot;
    double tauEnd = 1;
    double lineHeight = 16;       // of the label text, in pixels
    double tauAt(double x) const; // screen x -> tau
};

// labelPixels: the label font's pixel size, traceLabelPixels of the view's font.
TraceLayout traceLayout(const QRectF& area, const TeachingRun& run, double labelPixels);
int traceLabelPixels(const QFont& viewFont);
void paintTraces(QPainter& p, const QRectF& area, const TeachingRun& run, double cursorTau);

} // namespace kinstab::ui
