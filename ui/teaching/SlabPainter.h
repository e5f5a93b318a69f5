// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The side view of the slab on its two walls, drawn with QPainter so the same code paints the
// widget, a PNG and an SVG. Wall width and bearing are to scale; the span between the walls is
// shortened (a break in the slab says so), and the camera rides with the base: the walls stay
// put, the fixed ground ruler beneath scrolls by the base displacement.

#include "ui/teaching/TeachingRun.h"

#include <QRectF>

class QPainter;

#include "ui/Units.h"

namespace kinstab::ui {

struct SlabScene {
    TeachingFrame frame;
    TeachingParams params;
    double tstar = 0.099;
    double displayEnd = 0;
    ExitSide exit = ExitSide::None;    // planar collapse: across or along the walls
    UnitSystem units = UnitSystem::SI; // lengths in mm or in (View → Units)
};

// The header (state, time, displacements) and the side view; for the planar model the side view
// takes the left part and the top view (TopViewPainter) the right.
void paintSlabScene(QPainter& p, const QRectF& area, const SlabScene& scene);

} // namespace kinstab::ui
