// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The planar model's top view (as the paper's Fig. 36b): the two walls in plan, to scale along
// them (wall length = theta d / 2) and across (wall width d, bearing), the span shortened as in
// the side view; the slab where it started dotted, where it is now in its state's colour.

#include "ui/teaching/SlabPainter.h"

#include <QFont>
#include <QRectF>
#include <QString>

namespace kinstab::ui {

// Where the top view's words and plan go: the header above, the footer below, each wrapped to
// the area's width (the view may be 180 px wide at 1280 x 800), the plan in what is left. Where
// large text (presentation mode) would leave the plan less than half the height, the words
// take a smaller font.
struct TopViewLayout {
    QFont font;
    QString header, footer;
    QRectF headerRect, footerRect, plan;
};
inline constexpr int kTopViewTextFlags = Qt::AlignLeft | Qt::AlignVCenter | Qt::TextWordWrap;
TopViewLayout topViewLayout(const QFont& font, const QRectF& area, const SlabScene& scene);

void paintTopView(QPainter& p, const QRectF& area, const SlabScene& scene);

} // namespace kinstab::ui
