// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/Scrollable.h"

#include <QScrollArea>

namespace kinstab::ui {

QWidget* scrollable(QWidget* w) {
    auto* s = new QScrollArea;
    s->setWidget(w);
    s->setWidgetResizable(true);
    s->setFrameShape(QFrame::NoFrame);
    return s;
}

} // namespace kinstab::ui
