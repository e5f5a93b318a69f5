// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
// One colour per displayed state, shared by the drawing, the traces and the event log, so a
// student learns them once.

#include "ui/teaching/TeachingRun.h"

#include <QColor>
#include <QString>

namespace kinstab::ui {

QColor stateColor(DisplayState s);
// "slip →", "stick", ... as shown on screen.
QString stateLabel(DisplayState s, int direction);

} // namespace kinstab::ui
