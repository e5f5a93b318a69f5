// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// γc(A) at one frequency (the building's, like the paper's Fig. 34), with A_crit and the code
// ratios marked; and the excitation plot a(t)/A with its envelope.

#include "report/FigureData.h"

#include <QPainter>
#include <QRectF>

namespace kinstab::report {

void paintSlice(QPainter& p, const QRectF& area, const SliceData& s,
                const std::vector<CodeMark>& codes, const QString& gammaLabel);

struct ExcitationPlot {
    std::vector<double> timeSeconds;
    std::vector<double> accel;    // a(t) / A
    std::vector<double> envelope; // e(t) / S_max: the bound of a(t) / A
    QString title;
};

void paintExcitation(QPainter& p, const QRectF& area, const ExcitationPlot& e);

} // namespace kinstab::report
