// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// The side view of a free-standing block on its base, drawn with QPainter (the widget and an
// exported frame alike): the block to scale, tipped about the corner it rocks on and shifted by
// its sliding, its rest outline dashed, the base acceleration as an arrow, and a header with the
// mode, the time, theta/alpha and the sliding. The camera rides with the base.

#include "core/rocking/Block.h"
#include "core/rocking/RockingResult.h"
#include "ui/Units.h"

#include <QRectF>

class QPainter;

namespace kinstab::ui {

struct BlockScene {
    Block block;
    RockingSample state;
    double baseAcceleration = 0; // a_h, g
    bool overturned = false;
    bool impact = false; // an impact just happened (the scene flashes it)
    UnitSystem units = UnitSystem::SI;
};

// The world point of a block corner or its centre tipped by theta about the corner it rocks on
// (theta > 0: the corner at +x) and shifted by u, y up from the base (metres).
QPointF tippedPoint(const Block& b, double theta, double u, QPointF restPoint);

void paintBlockScene(QPainter& p, const QRectF& area, const BlockScene& scene);

} // namespace kinstab::ui
