// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/teaching/SlabAnimation.h"

#include <QPainter>

namespace kinstab::ui {

SlabAnimation::SlabAnimation(QWidget* parent) : QWidget(parent) {
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    setAttribute(Qt::WA_OpaquePaintEvent);
}

void SlabAnimation::setScene(const SlabScene& scene) {
    scene_ = scene;
    update();
}

void SlabAnimation::paintEvent(QPaintEvent*) {
    QPainter p(this);
    paintSlabScene(p, rect(), scene_);
}

} // namespace kinstab::ui
