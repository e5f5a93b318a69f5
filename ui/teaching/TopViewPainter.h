// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The planar model's top view (as the paper's Fig. 36b): the two walls in plan, to scale along
// them (wall length = theta d / 2) and across (wall width d, bearing), the span shortened as in
// the side view; the slab where it started dotted, where it is now in its state's colour.

#include "ui/teaching/SlabPainter.h"

namespace kinstab::ui {

void paintTopView(QPainter& p, const QRectF& area, const SlabScene& scene);

} // namespace kinstab::ui
