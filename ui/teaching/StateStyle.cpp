// SPDX-License-Identifier: GPL-3.0-or-later
#include "ui/teaching/StateStyle.h"

namespace kinstab::ui {

QColor stateColor(DisplayState s) {
    switch (s) {
    case DisplayState::AtRest:
    case DisplayState::Stick:
        return QColor(0x4a, 0x6f, 0xa5); // steel blue: moves with the walls
    case DisplayState::Slip:
        return QColor(0xe0, 0x7b, 0x00); // orange: sliding
    case DisplayState::Reversal:
        return QColor(0x8e, 0x44, 0xad); // purple: slides back at once
    case DisplayState::Collapse:
        return QColor(0xc0, 0x39, 0x2b); // red: off the wall
    case DisplayState::Stable:
        return QColor(0x2e, 0x8b, 0x57); // green: nothing more can happen
    case DisplayState::LiftOff:
        return QColor(0x8b, 0x00, 0x00);
    case DisplayState::Failed:
        return QColor(0x80, 0x80, 0x80);
    }
    return Qt::gray;
}

QString stateLabel(DisplayState s, int direction) {
    const QString name = QString::fromLatin1(displayStateName(s));
    if ((s == DisplayState::Slip || s == DisplayState::Reversal) && direction != 0)
        return name + (direction > 0 ? QStringLiteral(" →") : QStringLiteral(" ←"));
    return name;
}

} // namespace kinstab::ui
